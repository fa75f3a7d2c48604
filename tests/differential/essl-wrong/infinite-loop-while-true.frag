#version 300 es
// Chromium: rejects ("'' : Infinite loop detected in the shader"). essl: accepts (so does glslang). Found while minimising another case.
precision mediump float;
out vec4 o;
void main() {
    while (true) {}
    o = vec4(1.0);
}
