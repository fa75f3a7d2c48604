attribute vec4 a_position;
uniform int n;
varying float v[2];
void main() {
  v[n] = 1.0;
  gl_Position = a_position;
}
