#version 300 es
precision mediump float;
out vec4 o;
uniform highp vec4 u_shared;
uniform vec4 u_fragment;
void main() {
  o = u_fragment;
}
