precision mediump float;
varying float v[31];
void main() {
  gl_FragColor = vec4(v[30]);
}
