#version 300 es
precision mediump float;
out vec4 o;
void main() {
  float a = 1;
  int b = 1.0;
  o = vec4(c);
  float d = 1.0
  o = vec4(a);
}
