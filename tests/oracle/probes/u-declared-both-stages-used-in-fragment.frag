#version 300 es
precision mediump float;
out vec4 o;
uniform highp vec4 u_shared;
void main() {
  o = u_shared;
}
