#version 300 es
precision mediump float;
out vec4 o;
#define HAS(x) defined(x)
#if HAS(GL_ES)
#endif
void main() { o = vec4(1.0); }
