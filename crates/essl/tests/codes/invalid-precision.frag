#version 300 es
precision mediump float;
out vec4 o;
void main() {
  mediump bool b = true;
  o = vec4(b ? 1.0 : 0.0);
}
