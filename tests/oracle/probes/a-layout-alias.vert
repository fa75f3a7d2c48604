#version 300 es
layout(location=1) in vec4 a_x;
layout(location=1) in vec4 a_y;
void main() {
  gl_Position = a_x + a_y;
}
