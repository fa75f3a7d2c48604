#version 300 es
layout(location = 1) in vec4 a_fixed;
in mat2 a_m;
in vec4 a_v;
void main() {
  gl_Position = a_fixed + vec4(a_m[0], a_m[1]) + a_v;
}
