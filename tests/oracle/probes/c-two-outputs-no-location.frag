#version 300 es
precision mediump float;
out vec4 a;
out vec4 b;
void main() {
  a = vec4(1.0);
  b = vec4(0.0);
}
