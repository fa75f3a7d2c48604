#version 300 es
// The picture to blur, in HDR (values up to 6): a ring, a disc, a bar and a row of dots, each
// edge antialiased analytically over one pixel (no rasterised edge is inside the viewport).
precision highp float;
out vec4 o_color;

// 1 inside a band of half-width w around d = 0, 0 outside, linear over one pixel at the border.
float band(float d, float w) {
  return clamp(w - abs(d) + 0.5, 0.0, 1.0);
}

void main() {
  vec2 p = gl_FragCoord.xy;
  vec3 c = vec3(0.02, 0.03, 0.05);
  c += vec3(5.0, 2.0, 0.5) * band(length(p - vec2(42.3, 84.6)) - 24.0, 2.2);
  c += vec3(0.4, 1.5, 6.0) * band(length(p - vec2(90.7, 40.2)), 10.3);
  c += vec3(0.8, 4.0, 1.0) * band(0.8 * (p.y - 30.2) - 0.6 * (p.x - 20.1), 1.6) * band(p.x - 45.0, 30.2);
  vec2 cell = mod(p - vec2(3.3, 2.7), 16.0) - 8.0;
  c += vec3(3.0, 3.0, 3.0) * band(length(cell), 1.8) * band(p.y - 122.7, 6.0);
  o_color = vec4(c, 1.0);
}
