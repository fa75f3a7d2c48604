attribute vec4 a_position;
uniform int n;
uniform mat4 m;
void main() {
  gl_Position = m[n];
}
