#version 300 es
precision mediump float;
out vec4 o;
uniform vec4 u_light;
void main() { o = u_light; }
