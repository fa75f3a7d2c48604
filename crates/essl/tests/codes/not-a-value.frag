#version 300 es
precision mediump float;
out vec4 o;
float half_of(float x) { return x * 0.5; }
void main() {
  o = vec4(half_of);
}
