#version 300 es
// Reads a depth texture through a shadow sampler with reference 0.5.
precision highp float;
precision highp sampler2DShadow;
uniform sampler2DShadow u_texture;
in vec2 v_uv;
out vec4 o_color;
void main() {
  o_color = vec4(vec3(texture(u_texture, vec3(v_uv, 0.5))), 1.0);
}
