#version 300 es
precision mediump float;
out vec4 o;
float f(float p[16384]) {
  return p[0];
}
void main() {
  o = vec4(1.0);
}
