#version 300 es
in vec4 a_position;
out float v[2];
void main() {
  v[0] = 1.0;
  v[1] = 2.0;
  gl_Position = a_position;
}
