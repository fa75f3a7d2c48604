attribute vec4 a_position;
uniform int n;
float g[2];
void main() {
  g[0] = 1.0;
  g[1] = 2.0;
  gl_Position = a_position * g[n];
}
