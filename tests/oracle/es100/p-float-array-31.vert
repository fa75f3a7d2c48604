attribute vec4 a_position;
varying float v[31];
void main() {
  for (int i = 0; i < 31; i++) { v[i] = 0.0; }
  gl_Position = a_position;
}
