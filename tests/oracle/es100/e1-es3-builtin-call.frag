precision mediump float;
void main() {
  gl_FragColor = vec4(round(1.2));
}
