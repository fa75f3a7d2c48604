#version 300 es
precision mediump float;
out vec4 o;
uniform float x;
void main() {
  o = vec4(x);
}
