#version 300 es
// The sharp picture plus its blurred glow, tone mapped to 8 bits (Reinhard).
precision highp float;
uniform sampler2D u_sharp;
uniform sampler2D u_glow;
out vec4 o_color;
void main() {
  ivec2 xy = ivec2(gl_FragCoord.xy);
  vec3 c = 0.6 * texelFetch(u_sharp, xy, 0).rgb + 1.5 * texelFetch(u_glow, xy, 0).rgb;
  o_color = vec4(c / (1.0 + c), 1.0);
}
