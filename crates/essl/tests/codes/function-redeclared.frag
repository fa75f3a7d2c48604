#version 300 es
precision mediump float;
out vec4 o;
float f(float x);
int f(float x);
void main() { o = vec4(1.0); }
