#version 300 es
precision mediump float;
out vec4 o;
void clear() { o = vec4(0.0); }
void clear() { o = vec4(1.0); }
void main() { clear(); }
