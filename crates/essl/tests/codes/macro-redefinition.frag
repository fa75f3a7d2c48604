#version 300 es
precision mediump float;
out vec4 o;
#define SCALE 1.0
#define SCALE 2.0
void main() { o = vec4(SCALE); }
