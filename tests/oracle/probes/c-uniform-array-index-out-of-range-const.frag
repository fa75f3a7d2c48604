#version 300 es
precision mediump float;
out vec4 o;
uniform vec4 u_a[2];
void main() {
  o = u_a[2];
}
