#version 300 es
precision mediump float;
out vec4 o;
uniform float u[134217728];
void main() {
  o = vec4(u[0]);
}
