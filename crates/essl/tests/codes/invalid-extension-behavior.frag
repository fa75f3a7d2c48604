#version 300 es
#extension GL_EXT_frag_depth : maybe
precision mediump float;
out vec4 o;
void main() { o = vec4(1.0); }
