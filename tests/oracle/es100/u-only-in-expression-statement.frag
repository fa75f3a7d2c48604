precision mediump float;
uniform float u_dead;
uniform float u_used;
void main() {
  1.0 + u_dead;
  gl_FragColor = vec4(u_used);
}
