precision mediump float;
uniform float u;
uniform int n;
void main() {
  float s = 0.0;
  for (bool b = true; b != false; b = false) {
    s += 1.0;
  }
  gl_FragColor = vec4(s);
}
