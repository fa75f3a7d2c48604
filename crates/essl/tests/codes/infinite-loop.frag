#version 300 es
precision mediump float;
uniform float speed;
out vec4 color;
void main() {
    float t = 0.0;
    while (true) {
        t += speed;
    }
    color = vec4(t);
}
