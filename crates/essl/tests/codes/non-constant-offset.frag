#version 300 es
precision mediump float;
out vec4 o;
uniform sampler2D s;
uniform int k;
void main() {
  o = textureOffset(s, vec2(0.5), ivec2(k));
}
