precision mediump float;
uniform sampler2D s;
vec4 g = texture2D(s, vec2(0.5));
void main() {
  gl_FragColor = g;
}
