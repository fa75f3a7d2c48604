#version 300 es
precision mediump float;
out vec4 o;
uniform float u;
void main() {
  const float c = u;
  o = vec4(c);
}
