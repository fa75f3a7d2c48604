#version 300 es
// Chromium: compiles (ANGLE folds `?:` after it removes an `if (false)`, so the `if` stays). essl: rejected it (label-at-end-of-switch): its checker folded the condition to `false` at once.
precision mediump float;
uniform int u;
out vec4 o;
void main() {
    o = vec4(0.0);
    switch (u) {
        case 0:
            o = vec4(1.0);
            break;
        default:
            if (false ? u > 0 : false) break;
    }
}
