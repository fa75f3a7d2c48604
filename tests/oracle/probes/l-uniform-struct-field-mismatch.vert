#version 300 es
in vec4 a_position;
struct S {
  highp float a;
};
uniform S u_s;
void main() {
  gl_Position = a_position * u_s.a;
}
