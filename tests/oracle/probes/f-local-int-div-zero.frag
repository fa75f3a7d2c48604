#version 300 es
precision mediump float;
out vec4 o;
void main() {
  int x = 5 / (6 % 0);
  o = vec4(float(x));
}
