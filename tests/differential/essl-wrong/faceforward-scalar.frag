#version 300 es
// Chromium: compiles. essl: rejects (internal-error: naga rejects the lowered shader, "Call to builtin FaceForward has incorrect or ambiguous arguments"): faceforward(float, float, float).
precision mediump float;
uniform float a;
out vec4 o;
void main() {
    o = vec4(faceforward(a, 1.0, 0.5));
}
