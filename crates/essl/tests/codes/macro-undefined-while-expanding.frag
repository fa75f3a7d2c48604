#version 300 es
precision mediump float;
out vec4 o;
#define ID(x) x
void main() {
  o = vec4(ID(
#undef ID
    1.0));
}
