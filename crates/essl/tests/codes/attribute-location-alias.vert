#version 300 es
layout(location = 0) in mat4 a_model;
layout(location = 2) in vec4 a_position;
void main() { gl_Position = a_model * a_position; }
