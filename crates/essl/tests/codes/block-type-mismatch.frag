#version 300 es
precision mediump float;
out vec4 o;
uniform Light { vec3 color; };
void main() { o = vec4(color, 1.0); }
