#version 300 es
in vec4 a_position;
uniform highp vec4 u_shared;
uniform vec4 u_vertexOnly;
void main() {
  gl_Position = a_position + u_shared + u_vertexOnly;
}
