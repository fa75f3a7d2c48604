#version 300 es
precision mediump float;
out vec4 o;
float f() {
  return 1.0;
}
void main() {
  float f = 2.0;
  o = vec4(f);
}
