attribute vec4 a_position;
varying float v[32];
void main() {
  for (int i = 0; i < 32; i++) { v[i] = 0.0; }
  gl_Position = a_position;
}
