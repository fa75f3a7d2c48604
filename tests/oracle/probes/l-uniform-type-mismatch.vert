#version 300 es
in vec4 a_position;
uniform vec3 u;
void main() {
  gl_Position = a_position + vec4(u, 0.0);
}
