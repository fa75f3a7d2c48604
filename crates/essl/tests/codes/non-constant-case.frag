#version 300 es
precision mediump float;
out vec4 o;
uniform int k;
uniform int m;
void main() {
  o = vec4(0.0);
  switch (k) {
  case m:
    o = vec4(1.0);
  }
}
