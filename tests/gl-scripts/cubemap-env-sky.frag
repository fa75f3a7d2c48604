#version 300 es
// The environment's sky for one cube face: the direction through this pixel (from the face's
// inverse view-projection) shaded as a horizon gradient with a soft sun.
precision highp float;
uniform mat4 u_inverseViewProjection;
in vec2 v_uv;
out vec4 o_color;
void main() {
  vec4 far = u_inverseViewProjection * vec4(v_uv * 2.0 - 1.0, 1.0, 1.0);
  vec3 d = normalize(far.xyz / far.w);
  vec3 sky = mix(vec3(0.85, 0.8, 0.7), vec3(0.25, 0.45, 0.85), clamp(d.y * 1.5, 0.0, 1.0));
  vec3 ground = mix(vec3(0.45, 0.4, 0.35), vec3(0.2, 0.25, 0.15), clamp(-d.y * 2.0, 0.0, 1.0));
  vec3 c = mix(ground, sky, smoothstep(-0.05, 0.05, d.y));
  float sun = max(dot(d, normalize(vec3(0.5, 0.6, -0.6))), 0.0);
  c += vec3(1.0, 0.8, 0.5) * pow(sun, 40.0);
  o_color = vec4(c, 1.0);
}
