#version 300 es
precision mediump float;
out vec4 o;
void main() {
  uniform float u;
  o = vec4(1.0);
}
