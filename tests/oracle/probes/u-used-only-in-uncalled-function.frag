#version 300 es
precision mediump float;
out vec4 o;
uniform float u_inFunction;
uniform float u_used;
float helper() {
  return u_inFunction;
}
void main() {
  o = vec4(u_used);
}
