#version 300 es
precision mediump float;
out vec4 o;
struct S {
  vec3 position;
  vec3 color;
};
uniform S u_spots[2];
void main() {
  o = vec4(u_spots[1].color, 1.0);
}
