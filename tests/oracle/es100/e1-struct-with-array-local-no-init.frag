precision mediump float;
struct A {
  float v[2];
};
void main() {
  A a;
  a.v[0] = 1.0;
  a.v[1] = 1.0;
  gl_FragColor = vec4(a.v[0]);
}
