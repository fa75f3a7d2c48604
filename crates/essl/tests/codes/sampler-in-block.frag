#version 300 es
precision mediump float;
out vec4 o;
uniform Material { sampler2D albedo; };
void main() { o = vec4(1.0); }
