precision mediump float;
struct T {
  float webgl_x;
};
void main() {
  T t = T(1.0);
  gl_FragColor = vec4(t.webgl_x);
}
