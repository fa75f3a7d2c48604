#version 300 es
in vec4 a_first;
layout(location=3) in vec4 a_position;
in vec2 a_last;
void main() {
  gl_Position = a_position + a_first + vec4(a_last, 0.0, 0.0);
}
