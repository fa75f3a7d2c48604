#version 300 es
precision mediump float;
out vec4 o;
#undef __FILE__
void main() { o = vec4(1.0); }
