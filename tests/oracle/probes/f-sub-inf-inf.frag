#version 300 es
precision mediump float;
out vec4 o;
const float n = (1.0 / 0.0) - (1.0 / 0.0);
void main() {
  float a[n != n ? 1 : -1];
  a[0] = 1.0;
  o = vec4(a[0]);
}
