#version 300 es
// A uniform block of 32 bytes (two vec4, std140) read by the fragment shader.
precision highp float;
layout(std140) uniform Colors {
  vec4 u_first;
  vec4 u_second;
};
out vec4 o_color;
void main() {
  o_color = u_first + u_second;
}
