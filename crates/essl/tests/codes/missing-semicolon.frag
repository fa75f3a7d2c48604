#version 300 es
precision mediump float;
out vec4 o;
uniform float scale
void main() {
  o = vec4(scale);
}
