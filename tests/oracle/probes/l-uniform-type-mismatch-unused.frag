#version 300 es
precision mediump float;
out vec4 o;
uniform highp vec4 u;
void main() {
  o = vec4(1.0);
}
