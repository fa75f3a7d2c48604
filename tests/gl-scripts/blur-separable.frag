#version 300 es
// One direction of a separable 9-tap Gaussian: texelFetch at -4..4 steps of u_step texels,
// coordinates clamped to the texture (as CLAMP_TO_EDGE would).
precision highp float;
uniform sampler2D u_source;
uniform ivec2 u_step;
uniform float u_weights[5];
out vec4 o_color;
void main() {
  ivec2 last = textureSize(u_source, 0) - 1;
  ivec2 xy = ivec2(gl_FragCoord.xy);
  vec4 c = u_weights[0] * texelFetch(u_source, xy, 0);
  for (int i = 1; i < 5; i++) {
    c += u_weights[i] * (texelFetch(u_source, clamp(xy + i * u_step, ivec2(0), last), 0) +
                         texelFetch(u_source, clamp(xy - i * u_step, ivec2(0), last), 0));
  }
  o_color = c;
}
