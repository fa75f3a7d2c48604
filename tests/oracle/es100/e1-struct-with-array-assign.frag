precision mediump float;
struct A {
  float v[2];
};
void main() {
  A a;
  A b;
  b.v[0] = 1.0;
  b.v[1] = 1.0;
  a = b;
  gl_FragColor = vec4(a.v[0]);
}
