#version 300 es
precision mediump float;
out vec4 o;
const vec2 w = vec2(1.0, 0.0) / vec2(0.0);
void main() {
  float a[w.x > 3.4e38 && w.y != w.y ? 1 : -1];
  a[0] = 1.0;
  o = vec4(a[0]);
}
