#version 300 es
precision mediump float;
out vec4 o;
float f(uniform float x) { return x; }
void main() { o = vec4(f(1.0)); }
