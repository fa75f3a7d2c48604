#version 300 es
precision highp float;
out vec4 o;
struct S {
  mediump float f;
};
uniform float h1;
uniform mediump float ma[2];
uniform vec2 h2;
uniform S s;
uniform mediump vec4 mv;
uniform vec3 ha[2];
uniform mediump float m;
void main() {
  o = vec4(h1 + ma[1] + s.f + m, h2, ha[1].x) + mv;
}
