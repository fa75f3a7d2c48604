precision mediump float;
varying float v;
float g = v;
void main() {
  gl_FragColor = vec4(g);
}
