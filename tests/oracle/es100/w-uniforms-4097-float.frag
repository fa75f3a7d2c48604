precision mediump float;
uniform float u[4097];
void main() {
  gl_FragColor = vec4(u[4096]);
}
