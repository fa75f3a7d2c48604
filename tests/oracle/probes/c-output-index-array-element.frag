#version 300 es
precision mediump float;
uniform int u;
layout(location = 0) out vec4 o[2];
void main() {
  o[0] = vec4(0.0);
  o[1] = vec4(0.0);
  o[1][u] = 1.0;
}
