precision mediump float;
void main() {
  gl_FragDepthEXT = 0.5;
  gl_FragColor = vec4(1.0);
}
