#extension GL_OES_standard_derivatives : enable
precision mediump float;
varying vec2 v;
void main() {
  gl_FragColor = vec4(dFdx(v.x) + fwidth(v.y));
}
