#version 300 es
precision mediump float;
out vec4 o;
uniform Light u_light;
void main() { o = vec4(1.0); }
