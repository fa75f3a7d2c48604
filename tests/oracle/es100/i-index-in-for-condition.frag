precision mediump float;
uniform float a[8];
uniform int n;
void main() {
  float s = 0.0;
  for (int i = 0; i < 3; i++) {
    s += a[i];
  }
  gl_FragColor = vec4(s);
}
