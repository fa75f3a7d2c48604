precision mediump float;
const float f = 1.0 / 0.0;
const int k = 3 / 0;
void main() {
  float a[k == 2147483647 ? 1 : -1];
  a[0] = f;
  gl_FragColor = vec4(a[0]);
}
