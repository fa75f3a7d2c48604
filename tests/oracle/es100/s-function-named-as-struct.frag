precision mediump float;
struct S {
  float x;
};
float S(float a) {
  return a;
}
void main() {
  gl_FragColor = vec4(1.0);
}
