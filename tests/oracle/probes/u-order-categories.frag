#version 300 es
precision mediump float;
out vec4 o;
uniform FB {
  vec4 fb;
};
uniform sampler2D f_tex;
uniform vec4 f_vec;
void main() {
  o = f_vec + fb + texture(f_tex, vec2(0.5));
}
