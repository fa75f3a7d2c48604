precision mediump float;
float sin = 2.0;
void main() {
  gl_FragColor = vec4(sin);
}
