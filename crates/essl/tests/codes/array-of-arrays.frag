#version 300 es
precision mediump float;
out vec4 o;
void main() {
  float[2] a[2];
  o = vec4(1.0);
}
