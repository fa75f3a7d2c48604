#version 300 es
precision mediump float;
out vec4 o;
uniform float u_dead;
uniform float u_used;
const bool k = false;
void main() {
  o = vec4(u_used);
  if (k) {
    o = vec4(u_dead);
  }
}
