precision mediump float;
void main() {
  int a = 1u;
  gl_FragColor = vec4(float(a));
}
