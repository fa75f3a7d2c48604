#version 300 es
precision mediump float;
out vec4 o;
in vec4 v;
void main() {
  v = vec4(0.0);
  o = v;
}
