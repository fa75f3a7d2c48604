#version 300 es
precision mediump float;
out vec4 o;
in bool v_on;
void main() { o = vec4(v_on ? 1.0 : 0.0); }
