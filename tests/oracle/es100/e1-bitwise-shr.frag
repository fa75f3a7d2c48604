precision mediump float;
void main() {
  int a = 4 >> 1;
  gl_FragColor = vec4(float(a));
}
