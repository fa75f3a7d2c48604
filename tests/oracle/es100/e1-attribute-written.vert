attribute vec4 a_position;
void main() {
  a_position = vec4(1.0);
  gl_Position = a_position;
}
