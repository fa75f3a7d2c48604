#version 300 es
// Chromium: compiles (warning: divide by zero error during constant folding). essl: rejects (non-constant-initializer: "global variable initializers must be constant expressions").
ivec2 g = ivec2(1) / ivec2(0);
void main() {
    gl_Position = vec4(g, 0, 1);
}
