#version 300 es
precision mediump float;
out vec4 o;
struct S {
  float x;
};
uniform bool c;
void main() {
  S a = S(1.0);
  S b = S(2.0);
  S r = c ? a : b;
  o = vec4(r.x);
}
