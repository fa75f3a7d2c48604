#version 300 es
precision mediump float;
out vec4 o;
void main() {
  float gl_Brightness = 1.0;
  o = vec4(gl_Brightness);
}
