#version 300 es
in vec4 a_unused;
layout(location = 0) in vec4 a_fixed;
in vec4 a_free;
void main() {
  gl_Position = a_fixed + a_free;
}
