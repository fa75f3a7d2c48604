#version 300 es
precision mediump float;
out vec4 o;
void main() {
  const float c;
  o = vec4(c);
}
