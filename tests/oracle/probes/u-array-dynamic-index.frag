#version 300 es
precision mediump float;
out vec4 o;
uniform vec3 u_a[4];
uniform int u_i;
void main() {
  o = vec4(u_a[u_i], 1.0);
}
