#version 300 es
precision mediump float;
out vec4 o;
void main() {
  int i = 1;
  (+i)++;
  o = vec4(i);
}
