#version 300 es
precision mediump float;
out vec4 o;
#define 2PI 6.28
void main() { o = vec4(1.0); }
