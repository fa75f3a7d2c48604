precision mediump float;
vec4 g = gl_FragCoord;
void main() {
  gl_FragColor = g;
}
