precision mediump float;
uniform float u;
invariant u;
void main() {
  gl_FragColor = vec4(u);
}
