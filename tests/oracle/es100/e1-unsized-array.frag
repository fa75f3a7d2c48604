precision mediump float;
uniform float a[];
void main() {
  gl_FragColor = vec4(1.0);
}
