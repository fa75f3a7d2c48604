#version 300 es
precision mediump float;
out vec4 o;
#elif 1
void main() { o = vec4(1.0); }
