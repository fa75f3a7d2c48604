#version 300 es
precision mediump float;
out vec4 o;
float sin(int a) { return 1.0; }
void main() {
  o = vec4(sin(1));
}
