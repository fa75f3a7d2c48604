#version 300 es
precision mediump float;
out vec4 o;
void main() {
  int n = 09;
  o = vec4(float(n));
}
