#version 300 es
// Chromium: rejects ("'[' : array indexes for fragment outputs must be constant integral expressions"). essl: accepts: a non-constant index into a (non-array) vec4 fragment output.
precision mediump float;
uniform int i;
out vec4 o;
void main() {
    o[i] = 1.0;
}
