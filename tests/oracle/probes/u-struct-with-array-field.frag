#version 300 es
precision mediump float;
out vec4 o;
struct T {
  float w[3];
  vec2 v;
};
uniform T u_t;
void main() {
  o = vec4(u_t.w[1], u_t.v, 1.0);
}
