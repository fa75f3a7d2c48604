#version 300 es
// Chromium: compiles. essl: rejected it (internal-error: naga rejects the lowered shader, "Division by zero"): the value of `(i = 0)` was lowered as the literal 0, a constant divisor to naga.
void main() {
    int i = 1;
    ivec2 v = ivec2(i) / (i = 0);
    gl_Position = vec4(v, 0.0, 1.0);
}
