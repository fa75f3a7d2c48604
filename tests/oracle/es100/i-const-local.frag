precision mediump float;
uniform float a[8];
uniform int n;
void main() {
  const int k = 2;
  gl_FragColor = vec4(a[k + 1]);
}
