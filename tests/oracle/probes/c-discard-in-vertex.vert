#version 300 es
in vec4 a_position;
void main() {
  if (a_position.x > 0.0) discard;
  gl_Position = a_position;
}
