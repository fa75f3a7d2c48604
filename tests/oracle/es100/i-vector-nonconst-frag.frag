precision mediump float;
uniform vec4 v;
uniform int n;
void main() {
  gl_FragColor = vec4(v[n]);
}
