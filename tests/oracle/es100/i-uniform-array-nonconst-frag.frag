precision mediump float;
uniform float a[3];
uniform int n;
void main() {
  gl_FragColor = vec4(a[n]);
}
