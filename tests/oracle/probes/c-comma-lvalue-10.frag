#version 300 es
precision mediump float;
out vec4 o;
float g = 0.0;
void f(inout float p) {
  (p, p) = 1.0;
}
void main() {
  float v = 0.0;
  float w = 1.0;
  f(v);
  o = vec4(v, w, g, 1.0);
}
