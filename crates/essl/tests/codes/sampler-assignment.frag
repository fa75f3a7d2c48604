#version 300 es
precision mediump float;
out vec4 o;
void copy(sampler2D a, sampler2D b) { a = b; }
void main() { o = vec4(1.0); }
