precision mediump float;
float sin(int a) { return 1.0; }
void main() {
  gl_FragColor = vec4(sin(1) + sin(1.0));
}
