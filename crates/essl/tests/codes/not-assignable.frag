#version 300 es
precision mediump float;
out vec4 o;
uniform float u;
void main() {
  u = 1.0;
  o = vec4(u);
}
