#version 300 es
precision mediump float;
uniform int u;
layout(location = 0) out vec4 o[2];
void main() {
  o[u] = vec4(1.0);
}
