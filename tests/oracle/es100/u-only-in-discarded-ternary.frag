precision mediump float;
uniform float u_dead;
uniform float u_used;
uniform bool u_b;
void main() {
  u_b ? u_dead : 1.0;
  gl_FragColor = vec4(u_used);
}
