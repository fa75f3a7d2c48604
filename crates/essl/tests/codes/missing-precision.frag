#version 300 es
out vec4 o;
void main() { o = vec4(1.0); }
