precision mediump float;
struct A {
  float v[2];
};
A f() { A a; a.v[0] = 1.0; a.v[1] = 1.0; return a; }
void main() {
  gl_FragColor = vec4(1.0);
}
