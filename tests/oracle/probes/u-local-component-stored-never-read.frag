#version 300 es
precision mediump float;
out vec4 o;
uniform float u_dead;
uniform float u_used;
void main() {
  vec4 c = vec4(1.0);
  c.a = u_dead;
  o = vec4(u_used);
}
