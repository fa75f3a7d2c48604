precision mediump float;
#define GL_M 1.0
void main() {
  gl_FragColor = vec4(GL_M);
}
