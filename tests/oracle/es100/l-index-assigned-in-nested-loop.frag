precision mediump float;
void main() {
  for (int i = 0; i < 5; i++) {
    for (int j = 0; j < 2; j++) {
      i++;
    }
  }
  gl_FragColor = vec4(1.0);
}
