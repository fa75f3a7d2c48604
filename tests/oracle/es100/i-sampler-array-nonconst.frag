precision mediump float;
uniform sampler2D s[2];
uniform int n;
void main() {
  gl_FragColor = texture2D(s[n], vec2(0.5));
}
