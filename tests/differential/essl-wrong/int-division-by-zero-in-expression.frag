#version 300 es
// Chromium: compiles (warning: divide by zero error during constant folding). essl: rejects (internal-error: naga rejects the lowered shader, "Division by zero"): a folded integer division by zero inside a non-constant initializer.
precision mediump float;
out vec4 o;
void main() {
    int x = 5 / (6 % 0);
    o = vec4(x);
}
