#version 300 es
precision mediump float;
out vec4 o;
uniform B {
  highp vec4 y;
};
void main() {
  o = y;
}
