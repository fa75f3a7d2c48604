precision mediump float;
uniform sampler2D s[32];
void main() {
  gl_FragColor = texture2D(s[31], vec2(0.5));
}
