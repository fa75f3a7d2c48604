precision mediump float;
uniform float u_dead[2];
uniform float u_used;
void main() {
  u_dead[1];
  gl_FragColor = vec4(u_used);
}
