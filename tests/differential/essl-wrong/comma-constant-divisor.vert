#version 300 es
// Chromium: compiles. essl: rejected it (internal-error: naga rejects the lowered shader, "Division by zero"): the comma's value is a constant vector holding 0, a constant divisor to naga.
uniform vec2 u1;
void main() {
    ivec4 v = ivec4(4) / (u1.x, ivec4(1, 1, 0, 0));
    gl_Position = vec4(v);
}
