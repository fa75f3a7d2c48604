precision mediump float;
struct S {
  float x;
};
uniform bool c;
void main() {
  S a = S(1.0);
  S b = S(2.0);
  S r = c ? a : b;
  gl_FragColor = vec4(r.x);
}
