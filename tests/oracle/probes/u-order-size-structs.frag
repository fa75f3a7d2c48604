#version 300 es
precision mediump float;
out vec4 o;
struct Big {
  mat4 m;
  float f;
};
struct Small {
  float f;
};
uniform Big u_big;
uniform vec4 u_v4;
uniform Small u_small;
uniform vec2 u_v2;
void main() {
  o = u_big.m[0] * u_big.f + u_v4 + vec4(u_small.f, u_v2, 1.0);
}
