precision mediump float;
varying float v[2];
void main() {
  gl_FragColor = vec4(v[0] + v[1]);
}
