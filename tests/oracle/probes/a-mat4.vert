#version 300 es
in vec4 a_position;
in mat4 a_matrix;
in vec2 a_after;
void main() {
  gl_Position = a_matrix * a_position + vec4(a_after, 0.0, 0.0);
}
