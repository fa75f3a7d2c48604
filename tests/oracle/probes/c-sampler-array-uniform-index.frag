#version 300 es
precision mediump float;
out vec4 o;
uniform sampler2D u_tex[3];
uniform int u_i;
void main() {
  o = texture(u_tex[u_i], vec2(0.5));
}
