#version 300 es
// Chromium: compiles. essl: rejects (internal-error: naga rejects the lowered shader, "The type of [N] doesn't match the type stored in [N]"): outerProduct(vec2, vec3) is a mat3x2.
precision mediump float;
uniform vec2 a;
uniform vec3 b;
out vec4 o;
void main() {
    mat3x2 m = outerProduct(a, b);
    o = vec4(m[0], m[2]);
}
