#version 300 es
#extension GL_OVR_multiview2 : require
precision mediump float;
out vec4 o;
void main() { o = vec4(1.0); }
