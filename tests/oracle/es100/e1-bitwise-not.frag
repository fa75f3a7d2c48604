precision mediump float;
void main() {
  int a = ~1;
  gl_FragColor = vec4(float(a));
}
