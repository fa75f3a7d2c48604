#version 300 es
precision mediump float;
out vec4 o;
#define T(x) x x x x x x x x x x
void main() {
  T(T(T(T(T(;)))))
  o = vec4(1.0);
}
