#version 300 es
precision mediump float;
out vec4 o;
out vec4 o2;
void main() { o = vec4(1.0); o2 = o; }
