precision mediump float;
void g() {
  struct S {
    float x;
  };
  S a;
}
void main() {
  S b;
  gl_FragColor = vec4(1.0);
}
