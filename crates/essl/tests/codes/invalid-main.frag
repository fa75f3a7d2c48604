#version 300 es
precision mediump float;
out vec4 o;
void main(float x) { o = vec4(x); }
