#version 300 es
#pragma STDGL invariant(all)
in vec4 a_position;
out vec4 v;
void main() {
  v = a_position;
  gl_Position = a_position;
}
