#version 300 es
in vec4 a0;
in vec4 a1;
in vec4 a2;
in vec4 a3;
in vec4 a4;
in vec4 a5;
in vec4 a6;
in vec4 a7;
in vec4 a8;
in vec4 a9;
in vec4 a10;
in vec4 a11;
in vec4 a12;
in vec4 a13;
in vec4 a14;
in vec4 a15;
in vec4 a16;
void main() {
  gl_Position = a0 + a1 + a2 + a3 + a4 + a5 + a6 + a7 + a8 + a9 + a10 + a11 + a12 + a13 + a14 + a15 + a16;
}
