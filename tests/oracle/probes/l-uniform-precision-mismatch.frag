#version 300 es
precision mediump float;
out vec4 o;
uniform mediump float u;
void main() {
  o = vec4(u);
}
