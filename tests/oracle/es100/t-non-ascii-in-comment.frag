precision mediump float;
// é你好
void main() {
  gl_FragColor = vec4(1.0);
}
