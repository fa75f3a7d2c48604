precision mediump float;
uniform float u;
float g = sin(u) + 1.0;
void main() {
  gl_FragColor = vec4(g);
}
