#version 300 es
precision mediump float;
out vec4 o;
uniform mat4 m44;
uniform mat4x2 m42;
uniform mat3x4 m34;
uniform mat2x4 m24;
uniform mat3 m33;
uniform mat3x2 m32;
uniform mat2x3 m23;
uniform mat2 m22;
uniform vec4 v4;
uniform vec3 v3;
void main() {
  o = vec4(m44[0][0] + m42[0][0] + m34[0][0] + m24[0][0] + m33[0][0] + m32[0][0] + m23[0][0] + m22[0][0]) + v4 + vec4(v3, 1.0);
}
