#version 300 es
precision mediump float;
out vec4 o;
uniform sampler2D s;
void main() {
  o = texture2D(s, vec2(0.5));
}
