precision mediump float;
uniform B {
  vec4 c;
};
void main() {
  gl_FragColor = c;
}
