#version 300 es
// Chromium: compiles. essl: rejects (internal-error: naga rejects the lowered shader): == on structs with an array member.
struct S { float f[2]; };
uniform S u;
void main() {
    gl_Position = vec4(u == S(float[](1.0, 2.0)) ? 1.0 : 0.0);
}
