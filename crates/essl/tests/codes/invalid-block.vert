#version 300 es
out Varyings { vec4 color; };
void main() { gl_Position = vec4(0.0); }
