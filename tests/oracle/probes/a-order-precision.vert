#version 300 es
in highp vec4 a_high;
in lowp vec4 a_low;
in mediump vec4 a_medium;
in mediump float a_mf;
void main() {
  gl_Position = a_high + a_low + a_medium * a_mf;
}
