precision mediump float;
uniform float u_live;
void main() {
  float a;
  a = u_live;
  gl_FragColor = vec4(a);
}
