#version 300 es
precision mediump float;
out vec4 o;
uniform float u = 1.0;
void main() { o = vec4(u); }
