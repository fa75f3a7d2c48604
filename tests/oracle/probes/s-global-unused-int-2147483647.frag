#version 300 es
precision mediump float;
out vec4 o;
int g[2147483647];
void main() {
  o = vec4(1.0);
}
