attribute vec4 a_position;
void main() {
  int k = 0;
  while (k < 5) {
    k++;
  }
  gl_Position = a_position * float(k);
}
