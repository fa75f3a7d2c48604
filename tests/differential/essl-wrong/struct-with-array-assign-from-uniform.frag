#version 300 es
// Chromium: compiles. essl: rejects (internal-error: naga rejects the lowered shader, "Composing 0's component type is not expected"): assigning a uniform struct with an array member.
precision mediump float;
struct S { vec2 a[2]; };
uniform S u;
S g;
out vec4 o;
void main() {
    g = u;
    o = vec4(g.a[0], g.a[1]);
}
