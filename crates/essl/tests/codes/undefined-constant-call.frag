#version 300 es
precision highp float;
out vec4 o;
const float fade = smoothstep(1.0, 0.0, 0.25);
void main() {
    o = vec4(fade);
}
