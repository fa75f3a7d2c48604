precision mediump float;
uniform float u_dead;
uniform float u_used;
float g(float a) { return a; }
void main() {
  g(u_dead);
  gl_FragColor = vec4(u_used);
}
