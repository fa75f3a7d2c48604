precision mediump float;
void main() {
  float a = 1.0f;
  gl_FragColor = vec4(a);
}
