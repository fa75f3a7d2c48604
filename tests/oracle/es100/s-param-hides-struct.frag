precision mediump float;
struct S {
  float x;
};
float f(S S) {
  return S.x;
}
void main() {
  gl_FragColor = vec4(f(S(1.0)));
}
