#version 300 es
// Chromium: rejects ("'f' : Function does not return a value"). essl: accepts: a non-void function without any return statement.
precision mediump float;
out vec4 o;
float f() {
}
void main() {
    o = vec4(1.0);
}
