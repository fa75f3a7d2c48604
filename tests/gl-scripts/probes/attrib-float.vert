#version 300 es
// A float attribute (vec2) at location 0: the clip position.
layout(location = 0) in vec2 a_position;
void main() {
  gl_Position = vec4(a_position, 0.0, 1.0);
}
