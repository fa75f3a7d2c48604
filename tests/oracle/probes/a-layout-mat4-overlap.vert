#version 300 es
layout(location=0) in mat4 a_m;
layout(location=2) in vec4 a_v;
void main() {
  gl_Position = a_m * a_v;
}
