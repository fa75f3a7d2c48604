#version 300 es
flat out float v_k;
void main() { v_k = 1.0; gl_Position = vec4(0.0); }
