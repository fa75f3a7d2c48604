attribute vec4 a_position;
attribute mat4 a_m;
void main() {
  gl_Position = a_m * a_position;
}
