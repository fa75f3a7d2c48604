#version 300 es
uniform float u;
out highp vec4 o;
void main() {
  o = vec4(u);
}
