#version 300 es
// Chromium: compiles. essl: rejects (internal-error: naga rejects the lowered shader, "Float literal is infinite"): unpackHalf2x16 of a run-time value.
in uint a;
void main() {
    gl_Position = vec4(unpackHalf2x16(a), 0.0, 1.0);
}
