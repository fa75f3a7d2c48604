#version 300 es
precision mediump float;
out vec4 o;
void main() {
  float f = 1.0;
  o = vec4(f(2.0));
}
