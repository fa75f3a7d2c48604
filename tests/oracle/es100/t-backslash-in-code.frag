precision mediump float;
void main() {
  float a = 1.0; \ a = 2.0;
  gl_FragColor = vec4(a);
}
