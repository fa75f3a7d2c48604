precision mediump float;
const float a[2];
void main() {
  gl_FragColor = vec4(1.0);
}
