#version 300 es
precision mediump float;
out vec4 o;
uniform int k;
void main() {
  o = vec4(0.0);
  switch (k) {
  case 1: o = vec4(1.0); break;
  case 1: break;
  }
}
