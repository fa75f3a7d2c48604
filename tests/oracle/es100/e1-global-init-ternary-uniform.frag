precision mediump float;
uniform float u;
float g = u > 0.0 ? u : 1.0;
void main() {
  gl_FragColor = vec4(g);
}
