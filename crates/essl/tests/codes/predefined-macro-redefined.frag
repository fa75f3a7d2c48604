#version 300 es
precision mediump float;
out vec4 o;
#define __VERSION__ 100
void main() { o = vec4(1.0); }
