precision mediump float;
void main() {
  float[2] a;
  a[0] = 1.0;
  gl_FragColor = vec4(a[0]);
}
