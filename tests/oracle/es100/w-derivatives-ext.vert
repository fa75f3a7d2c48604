attribute vec4 a_position;
varying vec2 v;
void main() {
  v = a_position.xy;
  gl_Position = a_position;
}
