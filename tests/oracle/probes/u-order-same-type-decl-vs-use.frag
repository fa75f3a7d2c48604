#version 300 es
precision mediump float;
out vec4 o;
uniform float u_z;
uniform float u_a;
uniform float u_m;
void main() {
  o = vec4(u_m, u_z, u_a, 1.0);
}
