#version 300 es
precision mediump float;
out vec4 o;
float f(float x) { return x; }
