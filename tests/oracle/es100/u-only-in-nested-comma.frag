precision mediump float;
uniform float u_dead;
uniform float u_used;
void main() {
  float a = (1.0, u_dead, u_used);
  gl_FragColor = vec4(a);
}
