#version 300 es
precision mediump float;
out vec4 o;
void main() {
  float a[16383];
  a[0] = 1.0;
  o = vec4(1.0);
}
