attribute vec4 a_position;
uniform int n;
uniform vec4 u;
void main() {
  gl_Position = vec4(u[n]);
}
