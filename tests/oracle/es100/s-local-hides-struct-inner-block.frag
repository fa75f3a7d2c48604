precision mediump float;
struct S {
  float x;
};
void main() {
  S a;
  a.x = 1.0;
  {
    float S = 2.0;
    a.x += S;
  }
  S b = a;
  gl_FragColor = vec4(b.x);
}
