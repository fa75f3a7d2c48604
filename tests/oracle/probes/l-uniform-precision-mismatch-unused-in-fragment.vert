#version 300 es
in vec4 a_position;
uniform float u;
void main() {
  gl_Position = a_position * u;
}
