precision mediump float;
varying mat2 v[2];
void main() {
  gl_FragColor = vec4(v[1][0], v[0][1]);
}
