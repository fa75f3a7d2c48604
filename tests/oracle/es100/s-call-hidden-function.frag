precision mediump float;
float f() {
  return 1.0;
}
void main() {
  float f = 2.0;
  gl_FragColor = vec4(f());
}
