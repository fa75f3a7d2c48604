struct A {
  float v[2];
};
attribute vec4 a_position;
uniform A u;
uniform int n;
void main() {
  gl_Position = a_position * u.v[n];
}
