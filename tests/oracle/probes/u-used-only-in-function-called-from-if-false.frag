#version 300 es
precision mediump float;
out vec4 o;
uniform float u_dead;
uniform float u_used;
float helper() {
  return u_dead;
}
void main() {
  o = vec4(u_used);
  if (false) {
    o = vec4(helper());
  }
}
