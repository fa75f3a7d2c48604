#version 300 es
precision mediump float;
out vec4 o;
struct Light { vec3 color; };
uniform Light light;
void main() {
  o = vec4(light.colour, 1.0);
}
