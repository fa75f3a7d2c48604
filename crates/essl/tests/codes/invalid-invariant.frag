#version 300 es
precision mediump float;
out vec4 o;
invariant in vec4 v;
void main() { o = v; }
