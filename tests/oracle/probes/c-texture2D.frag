#version 300 es
precision mediump float;
out vec4 o;
uniform sampler2D u_s;
void main() {
  o = texture2D(u_s, vec2(0.5));
}
