#version 300 es
precision mediump float;
out vec4 o;
void f(int p) { o = vec4(p); }
void main() {
  int i = 1;
  f(+i);
}
