#version 300 es
precision mediump float;
out vec4 o;
struct Light {
  struct Color { vec3 rgb; } color;
};
void main() { o = vec4(1.0); }
