#version 300 es
// Chromium: compiles (warning: undefined shift, operand out of range). essl: rejects (non-constant-initializer: "`const` variable `c` needs a constant initializer").
precision mediump float;
out vec4 o;
void main() {
    const int c = 1 << 40;
    o = vec4(c);
}
