precision mediump float;
void main() {
  int k = 0;
  do {
    k++;
  } while (k < 5);
  gl_FragColor = vec4(float(k));
}
