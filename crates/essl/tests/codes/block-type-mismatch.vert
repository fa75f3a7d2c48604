#version 300 es
uniform Light { vec4 color; };
void main() { gl_Position = color; }
