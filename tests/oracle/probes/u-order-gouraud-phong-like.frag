#version 300 es
precision mediump float;
out vec4 o;
in vec4 vVertexColor;
void main() {
  o = vVertexColor;
}
