#version 300 es
precision mediump float;
out vec4 o;
void main() {
  vec3 c = pow(vec3(0.5), 2.0);
  o = vec4(c, 1.0);
}
