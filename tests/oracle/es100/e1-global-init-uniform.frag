precision mediump float;
uniform float u;
float g = u;
void main() {
  gl_FragColor = vec4(g);
}
