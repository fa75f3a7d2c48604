#version 300 es
precision mediump float;
out vec4 o;
void main() {
  float a = 1.0 / 0.0;
  o = vec4(a);
}
