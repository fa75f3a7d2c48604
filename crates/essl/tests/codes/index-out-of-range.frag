#version 300 es
precision mediump float;
out vec4 o;
void main() {
  float a[3];
  a[3] = 1.0;
  o = vec4(a[0]);
}
