#version 300 es
precision highp float;
out vec4 o;
const int step = -7 % 3;
void main() {
    o = vec4(float(step));
}
