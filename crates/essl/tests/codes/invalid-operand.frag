#version 300 es
precision mediump float;
out vec4 o;
void main() {
  bool b = !1.0;
  o = vec4(1.0);
}
