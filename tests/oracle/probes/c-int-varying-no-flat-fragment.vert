#version 300 es
in vec4 a_position;
flat out int v_i;
void main() {
  v_i = 1;
  gl_Position = a_position;
}
