#version 300 es
in mat3 a_m3;
in mat2 a_m2;
in vec4 a_position;
void main() {
  gl_Position = a_position + vec4(a_m3[2] + vec3(a_m2[1], 0.0), 0.0);
}
