precision mediump float;
float f() { return 1.0 + \
 2.0; }
void main() {
  gl_FragColor = vec4(f());
}
