precision mediump float;
uniform vec4 u[4097];
void main() {
  gl_FragColor = u[4096];
}
