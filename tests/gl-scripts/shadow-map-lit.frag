#version 300 es
// Lambert lighting from a directional light, shadowed by a depth texture read through a
// comparison sampler (TEXTURE_COMPARE_MODE = COMPARE_REF_TO_TEXTURE, NEAREST). Each pixel
// averages a 7x7-texel window of comparisons that slides continuously with the point: 8x8
// taps at texel centres, the outer rows and columns weighted by the fraction of a texel they
// cover. No tap sits near a texel border, so a last-bit change of the point's coordinates
// changes the result by as little, and one texel more or less in the shadow map changes a
// pixel by less than 3/255.
precision highp float;
precision highp sampler2DShadow;
uniform sampler2DShadow u_shadowMap;
uniform mat4 u_lightViewProjection;
uniform vec3 u_toLight;  // unit vector towards the light
uniform vec3 u_color;
in vec3 v_world;
in vec3 v_normal;
out vec4 o_color;

void main() {
  vec3 n = normalize(v_normal);
  float lambert = max(dot(n, u_toLight), 0.0);
  // Offset along the normal, then a constant bias: no surface shadows itself within the window.
  vec4 lightClip = u_lightViewProjection * vec4(v_world + 0.1 * n, 1.0);
  vec3 p = lightClip.xyz / lightClip.w * 0.5 + 0.5;
  vec2 size = vec2(textureSize(u_shadowMap, 0));
  vec2 texel = p.xy * size - 3.5;  // the window's lower-left corner, in texels
  vec2 base = floor(texel);
  vec2 f = texel - base;
  float lit = 0.0;
  for (int j = 0; j < 8; j++) {
    float wy = j == 0 ? 1.0 - f.y : (j == 7 ? f.y : 1.0);
    for (int i = 0; i < 8; i++) {
      float wx = i == 0 ? 1.0 - f.x : (i == 7 ? f.x : 1.0);
      vec2 uv = (base + vec2(float(i), float(j)) + 0.5) / size;
      lit += wx * wy * texture(u_shadowMap, vec3(uv, p.z - 0.012));
    }
  }
  lit /= 49.0;
  o_color = vec4(u_color * (0.3 + 0.7 * lambert * lit), 1.0);
}
