precision mediump float;
void main() {
  float s = 0.0;
  for (int i = 0; i < 2; i++) {
    float i2 = float(i);
    s += i2;
  }
  gl_FragColor = vec4(s);
}
