#version 300 es
precision mediump float;
out vec4 o;
struct S {
  vec3 position;
  vec3 color;
};
uniform S u_spots[3];
uniform int u_i;
void main() {
  o = vec4(u_spots[u_i].color, 1.0);
}
