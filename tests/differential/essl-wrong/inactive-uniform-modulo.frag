#version 300 es
// Chromium: compiles. essl: rejected it (internal-error: naga rejects the lowered shader, "Division by zero"): a uniform read only by an unused expression is inactive, and its reading was lowered as a constant 0 that naga evaluated as a divisor.
precision mediump float;
layout(std140) uniform Block1 { uint bf2; };
out vec4 o;
void main() {
    uvec2(15U, bf2) % uvec2(bf2, 7);
    o = vec4(1.0);
}
