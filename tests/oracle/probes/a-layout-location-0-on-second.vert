#version 300 es
in vec4 a_first;
layout(location = 0) in vec4 a_second;
void main() {
  gl_Position = a_first + a_second;
}
