precision mediump float;
struct S {
  float x;
};
float S;
void main() {
  gl_FragColor = vec4(1.0);
}
