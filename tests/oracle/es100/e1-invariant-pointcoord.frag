precision mediump float;
invariant gl_PointCoord;
void main() {
  gl_FragColor = vec4(gl_PointCoord, 0.0, 1.0);
}
