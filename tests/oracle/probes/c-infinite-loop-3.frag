#version 300 es
precision mediump float;
out vec4 o;
uniform int u;
void main() {
  o = vec4(0.0);
  do {} while (true);
}
