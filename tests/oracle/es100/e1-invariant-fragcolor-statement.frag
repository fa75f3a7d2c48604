precision mediump float;
invariant gl_FragColor;
void main() {
  gl_FragColor = vec4(1.0);
}
