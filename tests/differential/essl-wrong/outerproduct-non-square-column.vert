#version 300 es
// Chromium: compiles. essl: rejects (internal-error: naga rejects the lowered shader, "Index 2 is out of bounds"): column 2 of outerProduct(vec2, vec3), a mat3x2.
uniform vec2 a;
uniform vec3 b;
void main() {
    gl_Position = vec4(outerProduct(a, b)[2], 0.0, 1.0);
}
