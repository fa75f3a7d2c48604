#version 300 es
precision mediump float;
out vec4 o;
float g(float x);
float f(float x) {
  return g(x);
}
float g(float x) {
  return x > 0.0 ? f(x - 1.0) : 0.0;
}
void main() {
  o = vec4(f(2.0));
}
