#version 300 es
precision mediump float;
out vec4 o;
void main() {
  vec3 c = smoothstep(vec3(0.0), vec3(1.0), 0.5);
  o = vec4(c, 1.0);
}
