#version 300 es
precision highp float;
out vec4 o;
uniform vec4 f_high;
uniform mediump mat2 f_mat2;
uniform mediump float f_float;
void main() {
  o = f_high + vec4(f_mat2[0], f_float, 1.0);
}
