precision mediump float;
uniform float u;
uniform int n;
void main() {
  const int K = 3;
  float s = 0.0;
  for (int i = 0; i < K; i++) {
    s += 1.0;
  }
  gl_FragColor = vec4(s);
}
