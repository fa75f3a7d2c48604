precision mediump float;
void main() {
  int k = 0;
  while (k < 5) {
    k++;
  }
  gl_FragColor = vec4(float(k));
}
