precision mediump float;
uniform sampler2D s[2];
uniform int n;
void main() {
  vec4 c = vec4(0.0);
  for (int i = 0; i < 2; i++) {
    c += texture2D(s[i], vec2(0.5));
  }
  gl_FragColor = c;
}
