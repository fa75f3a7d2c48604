#version 300 es
#extension GL_NV_shader_noperspective_interpolation : require
precision mediump float;
out vec4 o;
void main() { o = vec4(1.0); }
