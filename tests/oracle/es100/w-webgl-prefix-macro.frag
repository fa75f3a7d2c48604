precision mediump float;
#define webgl_M 1.0
void main() {
  gl_FragColor = vec4(webgl_M);
}
