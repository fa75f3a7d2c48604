precision mediump float;
varying int v;
void main() {
  gl_FragColor = vec4(float(v));
}
