precision mediump float;
void main() {
  int a = 3000000000;
  gl_FragColor = vec4(float(a));
}
