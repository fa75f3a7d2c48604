#version 300 es
precision mediump float;
out vec4 o;
uniform bool k;
void main() {
  float a[2]; float b[2];
  float c[2] = k ? a : b;
  o = vec4(c[0]);
}
