#version 300 es
in vec4 a_z;
in vec4 a_a;
in vec4 a_m;
void main() {
  gl_Position = a_m + a_z + a_a;
}
