#version 300 es
in vec4 a_position;
out vec4 v[4096];
void main() {
  gl_Position = a_position;
}
