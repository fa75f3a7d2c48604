precision mediump float;
varying float v[32];
void main() {
  gl_FragColor = vec4(v[31]);
}
