#version 300 es
// Colour and object id in one pass: a lit colour to COLOR_ATTACHMENT0 (RGBA8) and the object's
// id to COLOR_ATTACHMENT1 (R32UI, an unsigned integer output).
precision highp float;
uniform vec3 u_color;
uniform vec3 u_toLight;
uniform uint u_id;
in vec3 v_world;
in vec3 v_normal;
layout(location = 0) out vec4 o_color;
layout(location = 1) out uint o_id;
void main() {
  float lambert = max(dot(normalize(v_normal), u_toLight), 0.0);
  o_color = vec4(u_color * (0.35 + 0.65 * lambert), 1.0);
  o_id = u_id;
}
