#version 300 es
in vec4 a_position;
uniform float u_k[gl_MaxFragmentInputVectors];
void main() {
  gl_Position = a_position * u_k[0];
}
