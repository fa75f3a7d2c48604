#version 300 es
precision mediump float;
out vec4 o;
uniform float u_dead;
uniform float u_used;
void main() {
  float x = u_dead;
  x++;
  o = vec4(u_used);
}
