#version 300 es
// Chromium: compiles (warning: undefined shift, operand out of range). essl: rejects (internal-error: naga rejects the lowered shader, "Shift amount exceeds the bit width"): an int shifted by the uint constant 40u.
precision mediump float;
out vec4 o;
void main() {
    o = vec4(3 >> 40u);
}
