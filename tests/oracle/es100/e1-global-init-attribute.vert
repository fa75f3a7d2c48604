attribute vec4 a_position;
vec4 g = a_position;
void main() {
  gl_Position = g;
}
