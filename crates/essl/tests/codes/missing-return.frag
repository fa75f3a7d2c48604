#version 300 es
precision mediump float;
out vec4 o;
float f(float x) { x += 1.0; }
void main() { o = vec4(f(1.0)); }
