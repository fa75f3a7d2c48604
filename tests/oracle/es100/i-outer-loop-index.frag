precision mediump float;
uniform float a[8];
uniform int n;
void main() {
  float s = 0.0;
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 2; j++) {
      s += a[i + j];
    }
  }
  gl_FragColor = vec4(s);
}
