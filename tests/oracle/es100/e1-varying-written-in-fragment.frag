precision mediump float;
varying float v;
void main() {
  v = 2.0;
  gl_FragColor = vec4(v);
}
