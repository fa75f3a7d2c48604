#version 300 es
precision highp float;
#include "common.glsl"
in vec3 v_normal;
uniform vec3 u_lightDirection;
uniform vec4 u_color;
out vec4 outColor;
void main() {
  outColor = vec4(u_color.rgb * lambert(v_normal, u_lightDirection), u_color.a);
}
