#version 300 es
precision mediump float;
out vec4 o;
struct Light {
  vec3 position;
  vec3 color;
  float intensity;
};
uniform vec2 u_first;
uniform Light u_light;
uniform float u_last;
void main() {
  o = vec4(u_first, u_light.intensity + u_last, u_light.position.x);
}
