precision mediump float;
float webgl_f() { return 1.0; }
void main() {
  gl_FragColor = vec4(webgl_f());
}
