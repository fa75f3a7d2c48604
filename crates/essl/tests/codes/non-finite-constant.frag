#version 300 es
precision highp float;
out vec4 o;
const float big = 1e38 / 1e-5;
void main() {
    o = vec4(big);
}
