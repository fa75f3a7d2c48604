#version 300 es
// Shows a texture: texelFetch at this pixel, tinted by a soft vignette.
precision highp float;
uniform sampler2D u_image;
in vec2 v_uv;
out vec4 o_color;
void main() {
  vec4 c = texelFetch(u_image, ivec2(gl_FragCoord.xy), 0);
  vec2 d = v_uv - 0.5;
  o_color = vec4(c.rgb * (1.0 - 0.6 * dot(d, d)), 1.0);
}
