#version 300 es
in vec4 a_first;
in vec3 a_unused;
in vec2 a_last;
void main() {
  gl_Position = a_first + vec4(a_last, 0.0, 0.0);
}
