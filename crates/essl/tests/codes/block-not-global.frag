#version 300 es
precision mediump float;
out vec4 o;
void main() {
  uniform Light { vec4 color; };
  o = vec4(1.0);
}
