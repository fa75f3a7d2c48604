#version 300 es
precision mediump float;
out vec4 o;
in vec3 v_missing;
void main() {
  o = vec4(1.0);
}
