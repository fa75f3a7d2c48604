#version 300 es
precision mediump float;
uniform int channel;
out vec4 color;
void main() {
    color = vec4(0.0);
    color[channel] = 1.0;
}
