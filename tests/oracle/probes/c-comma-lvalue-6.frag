#version 300 es
precision mediump float;
out vec4 o;
float g = 0.0;
void f(out float p) {
  p = 2.0;
}
void main() {
  float v = 0.0;
  float w = 1.0;
  (1.0, v) = 2.0;
  o = vec4(v, w, g, 1.0);
}
