#version 300 es
// Chromium: rejects ("'assign' : l-value required", "Constant value cannot be passed for 'out' or 'inout' parameters"). essl: accepts (so does glslang): +i passed to an inout parameter.
precision mediump float;
out vec4 o;
void f(inout int p) { p += 1; }
void main() {
    int i = 1;
    f(+i);
    o = vec4(i);
}
