attribute vec4 a_position;
varying float v[2];
void main() {
  v[0] = 1.0;
  v[1] = 1.0;
  gl_Position = a_position;
}
