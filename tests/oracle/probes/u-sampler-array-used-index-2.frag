#version 300 es
precision mediump float;
out vec4 o;
uniform sampler2D u_tex[3];
void main() {
  o = texture(u_tex[2], vec2(0.5));
}
