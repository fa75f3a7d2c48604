precision mediump float;
varying bool v;
void main() {
  gl_FragColor = vec4(1.0);
}
