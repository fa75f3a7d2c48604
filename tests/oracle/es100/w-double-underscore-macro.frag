precision mediump float;
#define A__B 1.0
void main() {
  gl_FragColor = vec4(A__B);
}
