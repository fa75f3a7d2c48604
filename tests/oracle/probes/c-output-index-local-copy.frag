#version 300 es
precision mediump float;
out vec4 o;
uniform int u;
void main() {
  vec4 t = vec4(0.0);
  t[u] = 1.0;
  o = t;
}
