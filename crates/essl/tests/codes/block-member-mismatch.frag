#version 300 es
precision mediump float;
out vec4 o;
uniform Light { vec4 colour; };
void main() { o = colour; }
