#version 300 es
precision mediump float;
out vec4 o;
void pick(out sampler2D s) {}
void main() { o = vec4(1.0); }
