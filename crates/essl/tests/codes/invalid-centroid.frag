#version 300 es
precision mediump float;
out vec4 o;
centroid uniform float u;
void main() { o = vec4(u); }
