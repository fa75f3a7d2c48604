#version 300 es
precision mediump float;
out vec4 o;
const int k = (-2147483647 - 1) / -1;
void main() {
  float a[k == 2147483647 ? 1 : -1];
  a[0] = 1.0;
  o = vec4(a[0]);
}
