#version 300 es
// Chromium: rejects ("'assign' : l-value required": ANGLE keeps only the right operand of a comma whose left one has no effect, and here it has one). essl: agrees.
precision mediump float;
out vec4 o;
void main() {
    float v = 0.0;
    float w = 1.0;
    (w += 1.0, v) = 3.0;
    o = vec4(v, w, 0.0, 1.0);
}
