#version 300 es
// Shows the colour target with the picked object (id u_picked in the R32UI target, read through
// a usampler2D) tinted, and outlined where a pixel two steps away has another id.
precision highp float;
precision highp usampler2D;
uniform sampler2D u_color;
uniform usampler2D u_ids;
uniform uint u_picked;
out vec4 o_color;

uint idAt(ivec2 xy) {
  return texelFetch(u_ids, clamp(xy, ivec2(0), textureSize(u_ids, 0) - 1), 0).r;
}

void main() {
  ivec2 xy = ivec2(gl_FragCoord.xy);
  vec3 c = texelFetch(u_color, xy, 0).rgb;
  if (idAt(xy) == u_picked) {
    bool edge = idAt(xy + ivec2(2, 0)) != u_picked || idAt(xy - ivec2(2, 0)) != u_picked ||
                idAt(xy + ivec2(0, 2)) != u_picked || idAt(xy - ivec2(0, 2)) != u_picked;
    c = edge ? vec3(1.0, 0.85, 0.2) : mix(c, vec3(1.0, 0.9, 0.4), 0.35);
  }
  o_color = vec4(c, 1.0);
}
