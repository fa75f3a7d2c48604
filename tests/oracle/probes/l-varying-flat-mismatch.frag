#version 300 es
precision mediump float;
out vec4 o;
in vec3 v;
void main() {
  o = vec4(v, 1.0);
}
