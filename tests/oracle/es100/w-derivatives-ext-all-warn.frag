#extension all : warn
precision mediump float;
void main() {
  gl_FragColor = vec4(dFdx(1.0));
}
