attribute vec4 a_position;
uniform int n;
void main() {
  gl_Position = vec4(a_position[n]);
}
