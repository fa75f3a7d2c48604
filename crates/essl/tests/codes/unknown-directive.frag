#version 300 es
precision mediump float;
out vec4 o;
#include "lighting.glsl"
void main() { o = vec4(1.0); }
