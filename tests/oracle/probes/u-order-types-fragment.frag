#version 300 es
precision mediump float;
out vec4 o;
uniform mat4 u1_mat4;
uniform vec4 u2_vec4;
uniform float u3_float;
uniform sampler2D u4_tex;
uniform vec2 u5_vec2;
uniform mat3 u6_mat3;
uniform int u7_int;
uniform vec3 u8_vec3;
uniform bool u9_bool;
uniform mat2 u10_mat2;
void main() {
  float f = u1_mat4[0][0] + u2_vec4.x + u3_float + texture(u4_tex, u5_vec2).x + u6_mat3[0][0];
  f += float(u7_int) + u8_vec3.x + (u9_bool ? 1.0 : 0.0) + u10_mat2[1][1];
  o = vec4(f);
}
