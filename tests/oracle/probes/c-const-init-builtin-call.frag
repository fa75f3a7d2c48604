#version 300 es
precision mediump float;
out vec4 o;
const float c = sin(1.0);
const vec3 n = normalize(vec3(1.0, 2.0, 2.0));
void main() {
  o = vec4(n, c);
}
