precision mediump float;
struct A {
  float v[2];
};
float f(A a) { return a.v[1]; }
void main() {
  A a;
  a.v[0] = 1.0;
  a.v[1] = 1.0;
  gl_FragColor = vec4(f(a));
}
