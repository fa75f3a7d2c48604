#version 300 es
precision mediump float;
out vec4 o;
uniform sampler3D u_s;
void main() {
  o = texture(u_s, vec3(0.5));
}
