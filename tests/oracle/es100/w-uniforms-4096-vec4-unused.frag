precision mediump float;
uniform vec4 u[5000];
void main() {
  gl_FragColor = vec4(1.0);
}
