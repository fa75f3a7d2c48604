#version 300 es
// Chromium: compiles. essl: rejects (unsupported: "not supported by essl's lowering yet: `refract` on scalars"): refract(float, float, float).
precision mediump float;
uniform float a;
out vec4 o;
void main() {
    o = vec4(refract(a, 1.0, 0.5));
}
