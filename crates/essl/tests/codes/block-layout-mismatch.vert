#version 300 es
uniform Light { layout(row_major) mat4 m; };
void main() { gl_Position = m[0]; }
