precision mediump float;
float g(int a) { return float(a); }
void main() {
  float s = 0.0;
  for (int i = 0; i < 5; i++) {
    s += g(i);
  }
  gl_FragColor = vec4(s);
}
