#version 300 es
in vec4 a_position;
in float x;
void main() {
  gl_Position = a_position * x;
}
