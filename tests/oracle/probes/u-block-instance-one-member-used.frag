#version 300 es
precision mediump float;
out vec4 o;
uniform Block {
  vec4 a;
  vec4 b;
} blk;
uniform float u_plain;
void main() {
  o = blk.a * u_plain;
}
