precision mediump float;
void main() {
  int a = 5 % 2;
  gl_FragColor = vec4(float(a));
}
