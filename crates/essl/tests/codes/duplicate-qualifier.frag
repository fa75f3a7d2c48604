#version 300 es
precision mediump float;
out vec4 o;
uniform highp highp float u;
void main() { o = vec4(u); }
