#version 300 es
precision mediump float;
out vec4 o;
struct Light {
  vec3 position;
  vec3 color;
  float intensity;
};
uniform Light light;
void main() {
  o = vec4(light.color, 1.0);
}
