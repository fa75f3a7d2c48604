precision mediump float;
void main() {
  float x = 1.0;
  {
    struct x {
      float y;
    };
    x a = x(2.0);
    gl_FragColor = vec4(a.y);
  }
}
