#version 300 es
precision mediump float;
out vec4 o;
float g[16384];
void main() {
  g[0] = 1.0;
  o = vec4(g[0]);
}
