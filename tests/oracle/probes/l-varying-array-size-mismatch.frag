#version 300 es
precision mediump float;
out vec4 o;
in float v[3];
void main() {
  o = vec4(v[0] + v[2]);
}
