#version 300 es
precision mediump float;
out vec4 o;
uniform Light { vec4 color; } lights[2];
uniform int k;
void main() {
  o = lights[k].color;
}
