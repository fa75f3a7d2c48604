precision mediump float;
void main() {
  gl_FragColor = gl_FragCoord;
}
