#version 300 es
precision mediump float;
out vec4 o;
uniform vec4 u_f1;
uniform highp vec4 u_both;
uniform vec4 u_f0;
void main() {
  o = u_f1 + u_both + u_f0;
}
