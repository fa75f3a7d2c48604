#version 300 es
precision mediump float;
out vec4 o;
in vec3 v_uv;
void main() { o = vec4(v_uv, 1.0); }
