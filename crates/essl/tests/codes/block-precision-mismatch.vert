#version 300 es
uniform Light { highp vec4 color; };
void main() { gl_Position = color; }
