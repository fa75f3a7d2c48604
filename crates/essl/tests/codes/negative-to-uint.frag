#version 300 es
precision highp float;
out vec4 o;
const uint all_ones = uint(-1.0);
void main() {
    o = vec4(float(all_ones));
}
