#version 300 es
uniform highp float u_time;
void main() { gl_Position = vec4(u_time); }
