precision mediump float;
float f(float a) {
  float a = 2.0;
  return a;
}
void main() {
  gl_FragColor = vec4(f(1.0));
}
