#version 300 es
precision mediump float;
out vec4 o;
void main() {
  int a[2147483647];
  a[0] = 1;
  o = vec4(1.0);
}
