#version 300 es
precision highp float;
out vec4 o;
uniform mat4 h_a;
uniform mediump vec3 m_b;
uniform float h_c;
uniform mediump float m_d;
uniform vec2 h_e;
uniform lowp vec4 l_f;
uniform mediump mat3 m_g;
uniform int i_h;
uniform bool n_i;
uniform highp int hi_j;
void main() {
  o = h_a[0] + vec4(m_b, h_c) + vec4(m_d, h_e, float(i_h)) + l_f + vec4(m_g[1], n_i ? 1.0 : 0.0) + vec4(float(hi_j));
}
