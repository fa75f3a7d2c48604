#version 300 es
in vec4 a_position;
uniform sampler2D u_vtex;
uniform highp isampler2D u_vitex;
void main() {
  gl_Position = a_position + texture(u_vtex, vec2(0.5)) + vec4(texelFetch(u_vitex, ivec2(0), 0));
}
