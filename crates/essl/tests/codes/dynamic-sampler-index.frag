#version 300 es
precision mediump float;
out vec4 o;
uniform sampler2D t[3];
uniform int k;
void main() {
  o = texture(t[k], vec2(0.5));
}
