#version 300 es
precision mediump float;
out vec4 o;
uniform int u_i;
void main() {
  float x = 0.0;
  switch (u_i) {
    case 0:
      x = 1.0;
      break;
    default:
  }
  o = vec4(x);
}
