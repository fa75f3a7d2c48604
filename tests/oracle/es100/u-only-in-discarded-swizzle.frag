precision mediump float;
uniform vec4 u_dead;
uniform float u_used;
void main() {
  u_dead.x;
  gl_FragColor = vec4(u_used);
}
