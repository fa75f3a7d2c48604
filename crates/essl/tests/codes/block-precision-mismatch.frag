#version 300 es
precision mediump float;
out vec4 o;
uniform Light { mediump vec4 color; };
void main() { o = color; }
