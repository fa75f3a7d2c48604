#version 300 es
precision mediump float;
out vec4 o;
uniform Light { layout(column_major) mat4 m; };
void main() { o = m[0]; }
