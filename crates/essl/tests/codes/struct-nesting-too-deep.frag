#version 300 es
precision mediump float;
struct A { float x; };
struct B { A a; };
struct C { B b; };
struct D { C c; };
struct E { D d; };
out vec4 color;
void main() { color = vec4(1.0); }
