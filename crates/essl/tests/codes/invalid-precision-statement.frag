#version 300 es
precision mediump float;
out vec4 o;
precision highp vec3;
void main() { o = vec4(1.0); }
