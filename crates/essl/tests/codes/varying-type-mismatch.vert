#version 300 es
out vec2 v_uv;
void main() { v_uv = vec2(0.0); gl_Position = vec4(0.0); }
