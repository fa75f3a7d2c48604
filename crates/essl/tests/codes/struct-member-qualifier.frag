#version 300 es
precision mediump float;
out vec4 o;
struct Light {
  flat int id;
};
void main() { o = vec4(1.0); }
