attribute vec4 a_position;
varying vec3 a[10];
varying vec2 b[20];
varying float c[30];
varying vec4 d[5];
void main() {
  for (int i = 0; i < 10; i++) { a[i] = vec3(0.0); }
  for (int i = 0; i < 20; i++) { b[i] = vec2(0.0); }
  for (int i = 0; i < 30; i++) { c[i] = 0.0; }
  for (int i = 0; i < 5; i++) { d[i] = vec4(0.0); }
  gl_Position = a_position;
}
