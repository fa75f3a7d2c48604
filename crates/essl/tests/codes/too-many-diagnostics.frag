#version 300 es
precision mediump float;
out vec4 o;
#define A x = 1; x = 1; x = 1; x = 1; x = 1; x = 1; x = 1; x = 1; x = 1; x = 1;
#define B A A A A A A A A A A
#define C B B B B B B B B B B
void main() {
  float x;
  C C
  o = vec4(x);
}
