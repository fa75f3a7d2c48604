#version 300 es
precision mediump float;
out vec4 o;
void main() {
  vec3 v = vec4(1.0);
  o = vec4(v, 1.0);
}
