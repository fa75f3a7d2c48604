#version 300 es
precision mediump float;
out vec4 o;
void f() { return 1.0; }
void main() { o = vec4(1.0); }
