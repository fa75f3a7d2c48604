#version 300 es
precision mediump float;
out vec4 o;
struct Inner {
  vec3 a;
  float b;
};
struct Outer {
  Inner inner;
  vec2 c;
  Inner arr[2];
};
uniform Outer u_o;
void main() {
  o = vec4(u_o.inner.b, u_o.arr[1].a);
}
