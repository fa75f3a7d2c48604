#version 300 es
precision mediump float;
out vec4 o;
void main() {
  int a = 0xFFFFFFFF;
  o = vec4(float(a));
}
