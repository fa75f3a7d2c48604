attribute vec4 a_position;
varying bool v;
void main() {
  gl_Position = a_position;
}
