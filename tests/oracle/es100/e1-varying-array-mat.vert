attribute vec4 a_position;
varying mat2 v[2];
void main() {
  v[0] = mat2(1.0);
  v[1] = mat2(2.0);
  gl_Position = a_position;
}
