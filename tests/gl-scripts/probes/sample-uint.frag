#version 300 es
// Reads an unsigned-integer texture (usampler2D) and shows its red channel / 255.
precision highp float;
precision highp usampler2D;
uniform usampler2D u_texture;
in vec2 v_uv;
out vec4 o_color;
void main() {
  o_color = vec4(float(texture(u_texture, v_uv).r) / 255.0, 0.0, 0.0, 1.0);
}
