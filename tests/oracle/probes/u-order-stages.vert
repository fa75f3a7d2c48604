#version 300 es
in vec4 a_position;
uniform vec4 u_v2;
uniform highp vec4 u_both;
uniform vec4 u_v1;
void main() {
  gl_Position = a_position + u_v2 + u_both + u_v1;
}
