#version 300 es
in vec4 a_position;
out vec4 v;
void main() {
  v = a_position;
  gl_Position = a_position;
}
