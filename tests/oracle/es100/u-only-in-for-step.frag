precision mediump float;
uniform float u_dead;
uniform float u_used;
void main() {
  for (int i = 0; i < 2; i++, u_dead) {}
  gl_FragColor = vec4(u_used);
}
