#version 300 es
precision mediump float;
out vec4 o;
uniform mediump float u_time;
void main() { o = vec4(u_time); }
