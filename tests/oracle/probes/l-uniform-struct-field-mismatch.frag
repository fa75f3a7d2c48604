#version 300 es
precision mediump float;
out vec4 o;
struct S {
  highp float b;
};
uniform S u_s;
void main() {
  o = vec4(u_s.b);
}
