precision mediump float;
varying float v;
void main() {
  gl_FragColor = vec4(1.0);
}
