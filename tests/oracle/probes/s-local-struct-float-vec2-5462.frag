#version 300 es
precision mediump float;
out vec4 o;
struct S {
  float b;
  vec2 a;
};
void main() {
  S s[5462];
  s[0].b = 1.0;
  o = vec4(s[0].b);
}
