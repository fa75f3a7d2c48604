#version 300 es
precision mediump float;
out vec4 o;
uniform float u_dead;
uniform float u_used;
void main() {
  o = vec4(u_used);
  for (int i = 0; i < 0; ++i) {
    o = vec4(u_dead);
  }
}
