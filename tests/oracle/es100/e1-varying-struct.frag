struct S {
  float x;
};
precision mediump float;
varying S v;
void main() {
  gl_FragColor = vec4(1.0);
}
