#version 300 es
precision mediump float;
out vec4 o;
flat in int v_i;
void main() {
  o = vec4(float(v_i));
}
