#version 300 es
precision mediump float;
out vec4 o;
struct M {
  sampler2D tex;
  float k;
  vec2 uv;
};
uniform M u_m;
void main() {
  o = texture(u_m.tex, u_m.uv) * u_m.k;
}
