#version 300 es
precision mediump float;
out vec4 o;
uniform float u;
float g = u * 2.0;
void main() {
  o = vec4(g);
}
