#version 300 es
precision mediump float;
out vec4 o;
void main() {
  vec3 v = vec3(1.0);
  o = vec4(smoothstep(v, v, 0.5), 1.0);
}
