#version 300 es
precision mediump float;
out vec4 o;
void main() {
  float half_of(float x) { return x * 0.5; }
  o = vec4(1.0);
}
