#version 300 es
precision mediump float;
out vec4 o;
float sin(int x) {
  return float(x);
}
void main() {
  o = vec4(sin(1));
}
