attribute vec4 a_position;
void main() {
  attribute vec4 b;
  gl_Position = a_position;
}
