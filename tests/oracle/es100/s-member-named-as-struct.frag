precision mediump float;
struct S {
  float x;
};
struct T {
  S S;
  S t;
};
void main() {
  T v = T(S(1.0), S(2.0));
  gl_FragColor = vec4(v.S.x + v.t.x);
}
