precision mediump float;
void g(out int a) { a = 1; }
void main() {
  for (int i = 0; i < 5; i++) {
    g(i);
  }
  gl_FragColor = vec4(1.0);
}
