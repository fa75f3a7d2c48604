#version 300 es
in float a1_float;
in vec4 a2_vec4;
in ivec2 a3_ivec2;
in vec3 a4_vec3;
in uvec4 a5_uvec4;
in vec2 a6_vec2;
void main() {
  gl_Position = vec4(a6_vec2, a1_float, 1.0) + a2_vec4 + vec4(vec2(a3_ivec2), 0.0, 0.0)
    + vec4(a4_vec3, float(a5_uvec4.x));
}
