#version 300 es
precision mediump float;
out vec4 o;
#define CAT(a, b) a ## b
void main() { o = vec4(1.0); }
