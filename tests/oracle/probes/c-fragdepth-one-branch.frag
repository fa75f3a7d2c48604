#version 300 es
precision mediump float;
out vec4 o;
uniform float u;
void main() {
  o = vec4(1.0);
  if (u > 0.5) {
    gl_FragDepth = 0.25;
  }
}
