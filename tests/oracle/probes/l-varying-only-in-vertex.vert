#version 300 es
in vec4 a_position;
out vec3 v_extra;
void main() {
  v_extra = a_position.xyz;
  gl_Position = a_position;
}
