#version 300 es
precision mediump float;
out vec4 o;
void main() {
  uint u = 4294967296u;
  o = vec4(float(u));
}
