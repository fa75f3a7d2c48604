#version 300 es
in vec4 a_position;
uniform highp vec4 u_shared;
void main() {
  gl_Position = a_position;
}
