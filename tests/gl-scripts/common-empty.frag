#version 300 es
// No colour output: the pass writes depth (and stencil) only.
precision mediump float;
void main() {
}
