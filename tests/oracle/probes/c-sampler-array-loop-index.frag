#version 300 es
precision mediump float;
out vec4 o;
uniform sampler2D u_tex[3];
void main() {
  o = vec4(0.0);
  for (int i = 0; i < 3; ++i) {
    o += texture(u_tex[i], vec2(0.5));
  }
}
