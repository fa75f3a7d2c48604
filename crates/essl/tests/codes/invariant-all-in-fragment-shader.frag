#version 300 es
precision mediump float;
out vec4 o;
#pragma STDGL invariant(all)
void main() { o = vec4(1.0); }
