precision mediump float;
float f(float a);
float f(float a);
float f(float a) { return a; }
void main() {
  gl_FragColor = vec4(f(1.0));
}
