#version 300 es
precision mediump float;
out vec4 o;
struct S {
  float x[20000];
};
void main() {
  o = vec4(1.0);
}
