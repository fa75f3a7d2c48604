#version 300 es
precision mediump float;
// `Light` here is another struct than the vertex shader's (not shared: no link error).
struct Light {
  vec4 color;
  float loop;
};
uniform Light u_fragmentLight;
uniform float u;
uniform float gl;
in vec2 v_uv;
out vec4 color;
void main() {
  color = u_fragmentLight.color * u_fragmentLight.loop * v_uv.x * u * gl;
}
