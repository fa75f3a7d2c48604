precision mediump float;
uniform float u;
uniform int n;
void main() {
  float s = 0.0;
  for (int i = 0; i < 5; i++) {
    i = 3;
  }
  gl_FragColor = vec4(s);
}
