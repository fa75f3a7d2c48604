precision mediump float;
struct S {
  float x;
};
void main() {
  float S = 1.0;
  gl_FragColor = vec4(S);
}
