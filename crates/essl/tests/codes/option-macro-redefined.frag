#version 300 es
precision mediump float;
out vec4 o;
#define FROM_OPTIONS 2.0
void main() { o = vec4(FROM_OPTIONS); }
