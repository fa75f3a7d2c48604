#version 300 es
precision mediump float;
out vec4 o;
void main() {
  vec2 v = vec2(1.0);
  o = vec4(v.size());
}
