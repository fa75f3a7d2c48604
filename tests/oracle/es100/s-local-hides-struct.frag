precision mediump float;
struct S {
  float x;
};
void main() {
  S S;
  S.x = 1.0;
  gl_FragColor = vec4(S.x);
}
