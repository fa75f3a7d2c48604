#version 300 es
out highp vec4 o;
void main() {
  float x = 1.0;
  o = vec4(x);
}
