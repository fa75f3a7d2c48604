precision mediump float;
void main() {
  float a[2];
  a[0] = 1.0;
  a[1] = 1.0;
  gl_FragColor = vec4(float(a.length()));
}
