#version 300 es
precision mediump float;
out vec4 o;
float sin(float x) {
  return x;
}
void main() {
  o = vec4(sin(1.0));
}
