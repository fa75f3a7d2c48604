#version 300 es
// One colour, Lambert-lit by a fixed directional light (u_toLight, a unit vector), plus ambient.
precision highp float;
uniform vec3 u_color;
uniform vec3 u_toLight;
in vec3 v_world;
in vec3 v_normal;
out vec4 o_color;
void main() {
  float lambert = max(dot(normalize(v_normal), u_toLight), 0.0);
  o_color = vec4(u_color * (0.35 + 0.65 * lambert), 1.0);
}
