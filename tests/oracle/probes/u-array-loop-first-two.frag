#version 300 es
precision mediump float;
out vec4 o;
uniform vec3 u_a[4];
void main() {
  vec3 s = vec3(0.0);
  for (int i = 0; i < 2; ++i) {
    s += u_a[i];
  }
  o = vec4(s, 1.0);
}
