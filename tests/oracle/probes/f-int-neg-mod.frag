#version 300 es
precision mediump float;
out vec4 o;
const int m = -7 % 3;
void main() {
  float a[m == 0 ? 1 : -1];
  a[0] = 1.0;
  o = vec4(a[0]);
}
