#version 300 es
precision mediump float;
out vec4 o;
in float v_k;
void main() { o = vec4(v_k); }
