precision mediump float;
void main() {
  mat3 m = mat3(mat4(1.0));
  mat4 n = mat4(mat2(1.0));
  gl_FragColor = vec4(m[0][0] + n[3][3]);
}
