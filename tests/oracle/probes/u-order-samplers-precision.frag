#version 300 es
precision mediump float;
out vec4 o;
uniform highp sampler2D s_high;
uniform lowp sampler2D s_low;
uniform mediump sampler2D s_medium;
uniform samplerCube s_cube;
void main() {
  o = texture(s_high, vec2(0.5)) + texture(s_low, vec2(0.5)) + texture(s_medium, vec2(0.5)) + texture(s_cube, vec3(1.0));
}
