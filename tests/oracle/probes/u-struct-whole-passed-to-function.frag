#version 300 es
precision mediump float;
out vec4 o;
struct Light {
  vec3 position;
  vec3 color;
  float intensity;
};
uniform Light light;
vec3 f(Light l) {
  return l.color;
}
void main() {
  o = vec4(f(light), 1.0);
}
