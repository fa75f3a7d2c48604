#version 300 es
in vec4 a_position;
uniform sampler2D v_tex;
uniform vec4 v_vec;
uniform VB {
  vec4 vb;
};
void main() {
  gl_Position = a_position + v_vec + vb + texture(v_tex, vec2(0.5));
}
