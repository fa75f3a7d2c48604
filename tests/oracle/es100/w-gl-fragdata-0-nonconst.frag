precision mediump float;
uniform int n;
void main() {
  gl_FragData[n] = vec4(1.0);
}
