#version 300 es
precision mediump float;
out vec4 o;
#define GL_SCALE 2.0
void main() { o = vec4(1.0); }
