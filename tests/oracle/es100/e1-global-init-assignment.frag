precision mediump float;
float a = 1.0;
float b = (a = 2.0);
void main() {
  gl_FragColor = vec4(b);
}
