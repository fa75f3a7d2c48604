#version 300 es
precision mediump float;
out vec4 o;
uniform int k;
void main() {
  switch (k) {
    o = vec4(0.0);
  case 1:
    o = vec4(1.0);
  }
}
