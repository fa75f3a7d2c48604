#version 300 es
precision mediump float;
out vec4 o;
#define MY__SCALE 2.0
void main() { o = vec4(MY__SCALE); }
