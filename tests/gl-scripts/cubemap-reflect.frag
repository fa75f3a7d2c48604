#version 300 es
// A mirror with a tint: the cube map sampled along the reflected view ray, Schlick's Fresnel.
precision highp float;
uniform samplerCube u_environment;
uniform vec3 u_eye;
uniform vec3 u_color;
in vec3 v_world;
in vec3 v_normal;
out vec4 o_color;
void main() {
  vec3 n = normalize(v_normal);
  vec3 v = normalize(v_world - u_eye);
  vec3 r = reflect(v, n);
  float f = 0.15 + 0.85 * pow(1.0 - max(dot(-v, n), 0.0), 5.0);
  vec3 c = texture(u_environment, r).rgb * mix(u_color, vec3(1.0), f);
  o_color = vec4(c, 1.0);
}
