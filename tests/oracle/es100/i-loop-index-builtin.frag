precision mediump float;
uniform float a[8];
uniform int n;
void main() {
  float s = 0.0;
  for (float f = 0.0; f < 3.0; f++) {
    s += a[int(floor(f))];
  }
  gl_FragColor = vec4(s);
}
