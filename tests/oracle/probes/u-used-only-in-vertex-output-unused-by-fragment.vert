#version 300 es
in vec4 a_position;
uniform vec4 u_toVarying;
out vec4 v_unread;
void main() {
  v_unread = u_toVarying;
  gl_Position = a_position;
}
