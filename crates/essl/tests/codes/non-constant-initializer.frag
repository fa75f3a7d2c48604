#version 300 es
precision mediump float;
out vec4 o;
uniform float u;
void main() {
  const float c = u * 2.0;
  o = vec4(c);
}
