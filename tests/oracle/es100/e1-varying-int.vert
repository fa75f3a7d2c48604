attribute vec4 a_position;
varying int v;
void main() {
  v = 1;
  gl_Position = a_position;
}
