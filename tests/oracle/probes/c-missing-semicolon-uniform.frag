#version 300 es
precision mediump float;
out vec4 o;
uniform float u_a
uniform float u_b;
void main() {
  o = vec4(u_a + u_b);
}
