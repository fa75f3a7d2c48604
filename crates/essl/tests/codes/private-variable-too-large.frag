#version 300 es
precision mediump float;
out vec4 o;
void main() {
  float table[20000];
  o = vec4(1.0);
}
