#version 300 es
precision mediump float;
out vec4 o;
const float f = 1e38 + 3e38;
void main() {
  float a[f > 3.4e38 ? 1 : -1];
  a[0] = 1.0;
  o = vec4(a[0]);
}
