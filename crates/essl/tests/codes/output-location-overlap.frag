#version 300 es
precision mediump float;
layout(location = 0) out vec4 color;
layout(location = 0) out vec4 normal;
void main() { color = vec4(1.0); normal = color; }
