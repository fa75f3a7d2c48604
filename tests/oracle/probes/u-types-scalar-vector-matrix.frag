#version 300 es
precision mediump float;
out vec4 o;
uniform bool u_bool;
uniform bvec3 u_bvec3;
uniform uint u_uint;
uniform uvec2 u_uvec2;
uniform int u_int;
uniform ivec4 u_ivec4;
uniform mat3 u_mat3;
uniform mat2x3 u_mat2x3;
uniform mat4x2 u_mat4x2;
uniform mat4 u_mat4;
void main() {
  float f = u_bool ? 1.0 : 0.0;
  if (any(u_bvec3)) f += 1.0;
  f += float(u_uint) + float(u_uvec2.y) + float(u_int) + float(u_ivec4.w);
  f += u_mat3[0][0] + u_mat2x3[1][2] + u_mat4x2[3][1] + u_mat4[2][3];
  o = vec4(f);
}
