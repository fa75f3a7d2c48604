#version 300 es
precision mediump float;
out vec4 o;
uniform mat2 u_m[2];
void main() {
  o = vec4(u_m[1][0], u_m[0][1]);
}
