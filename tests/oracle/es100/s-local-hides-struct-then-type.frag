precision mediump float;
struct S {
  float x;
};
void main() {
  S S;
  S t;
  gl_FragColor = vec4(1.0);
}
