#version 300 es
// A soft round sprite: weight (1 - r^2)^3 over gl_PointCoord, 0 at the rim, so the pixels at a
// point's square border add almost nothing; drawn with additive blending.
precision highp float;
in vec3 v_color;
out vec4 o_color;
void main() {
  vec2 d = gl_PointCoord * 2.0 - 1.0;
  float w = max(1.0 - dot(d, d), 0.0);
  w = w * w * w;
  o_color = vec4(v_color * w * 0.6, w);
}
