#version 300 es
precision mediump float;
out vec4 o;
uniform highp float u_high;
uniform lowp float u_low;
uniform mediump float u_medium;
uniform float u_default;
void main() {
  o = vec4(u_high, u_low, u_medium, u_default);
}
