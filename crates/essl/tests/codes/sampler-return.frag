#version 300 es
precision mediump float;
out vec4 o;
uniform sampler2D s;
sampler2D pick() { return s; }
void main() { o = vec4(1.0); }
