precision mediump float;
struct S0 {
  float x;
};
struct S1 {
  S0 s;
};
struct S2 {
  S1 s;
};
struct S3 {
  S2 s;
};
struct S4 {
  S3 s;
};
uniform S4 u;
void main() {
  gl_FragColor = vec4(u.s.s.s.s.x);
}
