precision mediump float;
void main() {
  float sin = 2.0;
  gl_FragColor = vec4(sin);
}
