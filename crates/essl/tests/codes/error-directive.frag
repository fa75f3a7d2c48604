#version 300 es
precision mediump float;
out vec4 o;
#ifndef GL_ES
#error this shader needs GLSL ES
#endif
#error unsupported configuration
void main() { o = vec4(1.0); }
