struct S {
  float x;
};
attribute vec4 a_position;
varying S v;
void main() {
  gl_Position = a_position;
}
