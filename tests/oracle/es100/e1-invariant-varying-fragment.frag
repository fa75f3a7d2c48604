precision mediump float;
invariant varying float v;
void main() {
  gl_FragColor = vec4(v);
}
