#version 300 es
precision mediump float;
out vec4 o;
layout(std140) uniform Lights {
  vec4 colorA;
  mat4 m;
  float k[2];
};
void main() {
  o = colorA * k[1];
}
