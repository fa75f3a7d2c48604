precision mediump float;
struct A {
  float v[2];
};
void main() {
  A a;
  A b;
  a.v[0] = 1.0;
  a.v[1] = 1.0;
  b.v[0] = 1.0;
  b.v[1] = 1.0;
  gl_FragColor = vec4(a == b ? 1.0 : 0.0);
}
