#version 300 es
precision mediump float;
out vec4 o;
uniform Unused {
  vec4 x;
};
uniform float u_plain;
void main() {
  o = vec4(u_plain);
}
