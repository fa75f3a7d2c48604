#version 300 es
precision mediump float;
out vec4 o;
uniform vec4 u_rows[200000000];
void main() { o = vec4(1.0); }
