#version 300 es
// Chromium: compiles (warning: divide by zero error during constant folding). essl: rejects (non-constant-initializer: "`const` variable `c` needs a constant initializer").
precision mediump float;
out vec4 o;
void main() {
    const ivec2 c = ivec2(7) % ivec2(0, 2);
    o = vec4(c, 0, 1);
}
