#version 300 es
precision mediump float;
out vec4 o;
#define MIX(a, a) a
void main() { o = vec4(1.0); }
