attribute vec4 a_position;
uniform int n;
void main() {
  float a[3];
  a[0] = 1.0;
  a[1] = 1.0;
  a[2] = 1.0;
  gl_Position = a_position * a[n];
}
