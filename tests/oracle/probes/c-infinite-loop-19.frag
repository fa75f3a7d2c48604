#version 300 es
precision mediump float;
out vec4 o;
uniform int u;
bool g = true;
void main() {
  o = vec4(0.0);
  while (g) {}
}
