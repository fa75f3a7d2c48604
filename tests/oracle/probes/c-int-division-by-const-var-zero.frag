#version 300 es
precision mediump float;
out vec4 o;
const int z = 0;
uniform int u_i;
void main() {
  int a = u_i / z;
  o = vec4(float(a));
}
