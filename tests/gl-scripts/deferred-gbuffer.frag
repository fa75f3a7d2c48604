#version 300 es
// Geometry pass of a deferred renderer: three colour targets at once (drawBuffers with
// COLOR_ATTACHMENT0..2): albedo and specular strength (RGBA8), the unit normal (RGBA16F, w = 1
// where something was drawn) and the world position (RGBA32F).
precision highp float;
uniform vec3 u_albedo;
uniform float u_specular;
in vec3 v_world;
in vec3 v_normal;
layout(location = 0) out vec4 o_albedo;
layout(location = 1) out vec4 o_normal;
layout(location = 2) out vec4 o_position;
void main() {
  o_albedo = vec4(u_albedo, u_specular);
  o_normal = vec4(normalize(v_normal), 1.0);
  o_position = vec4(v_world, 1.0);
}
