#version 300 es
precision mediump float;
out vec4 o;
uniform int u;
void main() {
  o = vec4(0.0);
  for (int k = 0; k < 4; k++) o[k] = 1.0;
}
