#version 300 es
// Lighting pass of a deferred renderer: reads the three targets of the geometry pass with
// texelFetch at this pixel and sums 32 point lights from a uniform block (std140, bound with
// uniformBlockBinding + bindBufferBase); Blinn-Phong, (1 - d/r)^2 falloff, Reinhard tone map.
precision highp float;
uniform sampler2D u_albedo;
uniform sampler2D u_normal;
uniform sampler2D u_position;
uniform vec3 u_eye;
layout(std140) uniform Lights {
  vec4 u_lightPositionRadius[32];
  vec4 u_lightColor[32];
};
out vec4 o_color;
void main() {
  ivec2 xy = ivec2(gl_FragCoord.xy);
  vec4 normal = texelFetch(u_normal, xy, 0);
  if (normal.w == 0.0) {  // nothing was drawn here
    o_color = vec4(0.05, 0.05, 0.08, 1.0);
    return;
  }
  vec4 albedo = texelFetch(u_albedo, xy, 0);
  vec3 p = texelFetch(u_position, xy, 0).xyz;
  vec3 n = normalize(normal.xyz);
  vec3 v = normalize(u_eye - p);
  vec3 c = 0.06 * albedo.rgb;
  for (int i = 0; i < 32; i++) {
    vec3 d = u_lightPositionRadius[i].xyz - p;
    float dist = length(d);
    float falloff = max(1.0 - dist / u_lightPositionRadius[i].w, 0.0);
    vec3 l = d / dist;
    vec3 h = normalize(l + v);
    float diffuse = max(dot(n, l), 0.0);
    float specular = albedo.a * pow(max(dot(n, h), 0.0), 40.0);
    c += falloff * falloff * u_lightColor[i].rgb * (albedo.rgb * diffuse + specular);
  }
  o_color = vec4(c / (1.0 + c), 1.0);
}
