#version 300 es
precision mediump float;
out vec4 o;
float f() { return; }
void main() { o = vec4(f()); }
