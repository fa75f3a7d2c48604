#version 300 es
precision mediump float;
out vec4 o;
void main() {
  mat4 a[1024];
  a[0] = mat4(1.0);
  o = vec4(1.0);
}
