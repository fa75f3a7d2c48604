#version 300 es
precision mediump float;
out vec4 o;
void f(inout int p) { p += 1; }
void main() {
  int i = 1;
  f(+i);
  o = vec4(i);
}
