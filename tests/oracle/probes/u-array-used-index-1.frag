#version 300 es
precision mediump float;
out vec4 o;
uniform vec3 u_a[4];
void main() {
  o = vec4(u_a[1], 1.0);
}
