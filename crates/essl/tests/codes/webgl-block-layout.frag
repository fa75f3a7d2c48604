#version 300 es
precision mediump float;
out vec4 o;
layout(shared) uniform Light { vec4 color; };
void main() { o = color; }
