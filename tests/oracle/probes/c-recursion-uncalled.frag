#version 300 es
precision mediump float;
out vec4 o;
float f(float x) {
  return f(x);
}
void main() {
  o = vec4(1.0);
}
