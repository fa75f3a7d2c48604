#version 300 es
precision mediump float;
out vec4 o;
void main() { o = vec4(1.0); }
/* the end of the file comes first
