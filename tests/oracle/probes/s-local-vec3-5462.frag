#version 300 es
precision mediump float;
out vec4 o;
void main() {
  vec3 a[5462];
  a[0] = vec3(1.0);
  o = vec4(1.0);
}
