#version 300 es
precision mediump float;
out vec4 o;
uniform int n;
void main() {
  float a[n];
  o = vec4(1.0);
}
