precision mediump float;
uniform vec4 u[2048];
uniform vec4 w[2049];
void main() {
  gl_FragColor = u[1] + w[1];
}
