#version 300 es
in vec4 a_position;
uniform B {
  vec4 x;
};
void main() {
  gl_Position = a_position + x;
}
