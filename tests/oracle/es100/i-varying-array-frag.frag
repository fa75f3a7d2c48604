precision mediump float;
varying float v[2];
uniform int n;
void main() {
  gl_FragColor = vec4(v[n]);
}
