#version 300 es
precision mediump float;
out vec4 o;
uniform highp isamplerCube s;
void main() {
  o = vec4(texture(s, vec3(1.0)));
}
