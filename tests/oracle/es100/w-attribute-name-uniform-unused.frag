precision mediump float;
uniform float x;
void main() {
  gl_FragColor = vec4(x);
}
