precision mediump float;
uniform float u;
uniform int n;
void main() {
  float s = 0.0;
  for (float f = 0.0; f < 2.5; f += 0.5) {
    s += 1.0;
  }
  gl_FragColor = vec4(s);
}
