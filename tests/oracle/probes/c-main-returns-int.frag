#version 300 es
precision mediump float;
out vec4 o;
int main() {
  o = vec4(1.0);
  return 0;
}
