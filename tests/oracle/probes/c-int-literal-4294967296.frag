#version 300 es
precision mediump float;
out vec4 o;
void main() {
  int a = 4294967296;
  o = vec4(float(a));
}
