#version 300 es
precision mediump float;
out vec4 o;
struct S {
  vec3 position;
  vec3 color;
};
uniform S u_spots[2];
void main() {
  vec3 s = vec3(0.0);
  for (int i = 0; i < 2; ++i) {
    s += u_spots[i].position;
  }
  o = vec4(s, 1.0);
}
