#version 300 es
#define GL_FOO 1
precision mediump float;
out vec4 o;
void main() {
  o = vec4(1.0);
}
