precision mediump float;
uniform float u;
uniform int n;
void main() {
  float s = 0.0;
  for (int i = n; i < 5; i++) {
    s += 1.0;
  }
  gl_FragColor = vec4(s);
}
