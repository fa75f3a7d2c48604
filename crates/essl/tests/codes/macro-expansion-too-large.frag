#version 300 es
precision mediump float;
out vec4 o;
#define TWICE(x) x + x
void main() {
  float x = 1.0;
  o = vec4(TWICE(TWICE(TWICE(TWICE(TWICE(TWICE(TWICE(TWICE(TWICE(TWICE(TWICE(TWICE(TWICE(TWICE(x)))))))))))))));
}
