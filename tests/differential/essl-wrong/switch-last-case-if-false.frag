#version 300 es
// Chromium: rejects ("'switch' : no statement between the last case label and the end of the switch statement": ANGLE folds `if (false) break;` away). essl: accepts (so does glslang).
precision mediump float;
uniform int i;
out vec4 o;
void main() {
    switch (i) {
        case 0:
            o = vec4(1.0);
            break;
        default:
            if (false) break;
    }
}
