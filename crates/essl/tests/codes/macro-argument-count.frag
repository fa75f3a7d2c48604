#version 300 es
precision mediump float;
out vec4 o;
#define MIX(a, b) (a + b)
void main() {
  o = vec4(MIX(1.0));
}
