#version 300 es
in vec4 a_position;
void main() {
  a_position = vec4(0.0);
  gl_Position = a_position;
}
