#version 300 es
precision mediump float;
out vec4 o;
const ivec2 c = ivec2(7) % ivec2(0, 2);
void main() {
  float a[c == ivec2(2147483647, 1) ? 1 : -1];
  a[0] = 1.0;
  o = vec4(a[0]);
}
