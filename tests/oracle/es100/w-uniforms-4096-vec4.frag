precision mediump float;
uniform vec4 u[4096];
void main() {
  gl_FragColor = u[4095];
}
