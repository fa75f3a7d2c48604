#version 300 es
precision mediump float;
out vec4 o;
const float x = sqrt(vec2(4.0, -4.0)).x + sqrt(vec2(4.0, -4.0)).y;
void main() {
  float a[x == 2.0 ? 1 : -1];
  a[0] = 1.0;
  o = vec4(a[0]);
}
