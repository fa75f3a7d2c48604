precision mediump float;
float a = 1.0;
float b = a;
void main() {
  gl_FragColor = vec4(b);
}
