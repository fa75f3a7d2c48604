attribute vec4 a_position;
attribute float x;
void main() {
  gl_Position = a_position;
}
