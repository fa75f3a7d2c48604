struct S {
  float x;
};
attribute vec4 a_position;
uniform S u[2];
uniform int n;
void main() {
  gl_Position = a_position * u[n].x;
}
