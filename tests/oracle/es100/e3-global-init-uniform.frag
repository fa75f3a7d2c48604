#version 300 es
precision mediump float;
out vec4 o;
uniform float u;
float g = u;
void main() {
  o = vec4(g);
}
