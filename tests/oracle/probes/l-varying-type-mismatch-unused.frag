#version 300 es
precision mediump float;
out vec4 o;
in vec4 v;
void main() {
  o = vec4(1.0);
}
