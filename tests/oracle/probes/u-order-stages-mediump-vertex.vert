#version 300 es
precision mediump float;
in vec4 a_position;
uniform mat4 v_mat;
uniform highp vec4 v_high;
uniform float v_float;
void main() {
  gl_Position = v_mat * a_position + v_high * v_float;
}
