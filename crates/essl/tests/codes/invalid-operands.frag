#version 300 es
precision mediump float;
out vec4 o;
void main() {
  o = vec4(vec2(1.0) + vec3(1.0), 1.0);
}
