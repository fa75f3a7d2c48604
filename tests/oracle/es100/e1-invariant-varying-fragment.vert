attribute vec4 a_position;
invariant varying float v;
void main() {
  v = 1.0;
  gl_Position = a_position;
}
