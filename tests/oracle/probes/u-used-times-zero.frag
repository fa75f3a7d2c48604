#version 300 es
precision mediump float;
out vec4 o;
uniform float u_zero;
uniform float u_used;
void main() {
  o = vec4(u_used + u_zero * 0.0);
}
