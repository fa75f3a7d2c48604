#version 300 es
precision mediump float;
out vec4 o;
int g = 1 / 0;
void main() {
  o = vec4(float(g));
}
