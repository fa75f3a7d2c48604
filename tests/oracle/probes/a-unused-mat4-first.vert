#version 300 es
in mat4 a_unusedMatrix;
in vec4 a_position;
void main() {
  gl_Position = a_position;
}
