precision mediump float;
float sin(float a) { return 1.0; }
void main() {
  gl_FragColor = vec4(sin(1.0));
}
