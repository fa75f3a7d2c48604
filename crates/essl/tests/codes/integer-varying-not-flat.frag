#version 300 es
precision mediump float;
out vec4 o;
in int v_id;
void main() { o = vec4(float(v_id)); }
