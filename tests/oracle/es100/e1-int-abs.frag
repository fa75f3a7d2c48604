precision mediump float;
void main() {
  int a = abs(-1);
  gl_FragColor = vec4(float(a));
}
