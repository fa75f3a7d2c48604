#version 300 es
precision mediump float;
out vec4 o;
float fact(float n) { return n <= 1.0 ? 1.0 : n * fact(n - 1.0); }
void main() { o = vec4(fact(3.0)); }
