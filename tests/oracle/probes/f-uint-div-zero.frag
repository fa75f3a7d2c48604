#version 300 es
precision mediump float;
out vec4 o;
const uint u = 1u / (2u - 2u);
void main() {
  float a[u == 4294967295u ? 1 : -1];
  a[0] = 1.0;
  o = vec4(a[0]);
}
