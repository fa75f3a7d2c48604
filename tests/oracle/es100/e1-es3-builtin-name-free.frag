precision mediump float;
float round(float a) { return floor(a + 0.5); }
float texture(float a) { return a; }
void main() {
  gl_FragColor = vec4(round(1.2) + texture(1.0));
}
