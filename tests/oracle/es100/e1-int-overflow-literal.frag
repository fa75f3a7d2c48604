precision mediump float;
void main() {
  int a = 4294967296;
  gl_FragColor = vec4(float(a));
}
