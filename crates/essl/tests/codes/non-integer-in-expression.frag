#version 300 es
precision mediump float;
out vec4 o;
#if __VERSION__ > 2.5
#endif
void main() { o = vec4(1.0); }
