#version 300 es
uniform highp float u;
out highp vec4 o;
void main() {
  highp float x = u;
  o = vec4(x);
}
