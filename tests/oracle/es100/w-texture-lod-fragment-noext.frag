precision mediump float;
uniform sampler2D s;
void main() {
  gl_FragColor = texture2DLod(s, vec2(0.5), 1.0);
}
