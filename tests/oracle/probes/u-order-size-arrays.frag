#version 300 es
precision mediump float;
out vec4 o;
uniform float m_fa[8];
uniform mat3 m_m3;
uniform vec4 m_v4;
uniform vec2 m_v2a[3];
uniform float m_f;
void main() {
  o = vec4(m_fa[7], m_m3[2][2], m_v2a[2]) + m_v4 + vec4(m_f);
}
