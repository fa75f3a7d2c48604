#version 300 es
precision mediump float;
out vec4 o;
in vec3 v_normal;
void main() { o = vec4(v_normal, 1.0); }
