#version 300 es
precision mediump float;
out vec4 o;
const uvec2 u = uvec2(vec3(-2.0, 1.0, -1.0));
void main() {
  float a[u == uvec2(4294967294u, 1u) ? 1 : -1];
  a[0] = 1.0;
  o = vec4(a[0]);
}
