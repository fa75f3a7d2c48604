#version 300 es
precision mediump float;
out vec4 o;
void main() {
  float f = 1e39;
  o = vec4(f);
}
