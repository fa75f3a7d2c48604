#version 300 es
precision mediump float;
out vec4 o;
uniform float u_f[3];
void main() {
  o = vec4(u_f[0] + u_f[2]);
}
