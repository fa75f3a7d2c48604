#version 300 es
in vec4 a_position;
uniform vec4 u_v;
uniform highp vec4 u_shared;
void main() {
  gl_Position = a_position + u_v;
}
