struct S {
  float x;
};
attribute S a_s;
attribute vec4 a_position;
void main() {
  gl_Position = a_position;
}
