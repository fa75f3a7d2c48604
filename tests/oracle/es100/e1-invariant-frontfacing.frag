precision mediump float;
invariant gl_FrontFacing;
void main() {
  gl_FragColor = vec4(1.0);
}
