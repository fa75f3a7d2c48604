#version 300 es
precision mediump float;
out vec4 o;
uniform int u;
void main() {
  o = vec4(0.0);
  switch (u) {
    case 0:
      o = vec4(1.0);
      break;
    default:
      if (false && u > 0) break;
  }
}
