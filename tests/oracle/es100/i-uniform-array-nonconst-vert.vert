attribute vec4 a_position;
uniform float a[3];
uniform int n;
void main() {
  gl_Position = a_position * a[n];
}
