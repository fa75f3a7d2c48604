#version 300 es
precision mediump float;
out vec4 o;
const uint u = uint(-1.0);
void main() {
  float a[u == 4294967295u ? 1 : -1];
  a[0] = 1.0;
  o = vec4(a[0]);
}
