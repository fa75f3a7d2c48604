precision mediump float;
invariant gl_FragCoord;
void main() {
  gl_FragColor = gl_FragCoord;
}
