#version 300 es
// Chromium: rejects ("'bool' : illegal type for precision qualifier"). essl: accepts.
precision mediump float;
out vec4 o;
void main() {
    lowp bool b = true;
    o = vec4(b);
}
