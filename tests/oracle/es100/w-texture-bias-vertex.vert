attribute vec4 a_position;
uniform sampler2D s;
void main() {
  gl_Position = a_position + texture2D(s, vec2(0.5), 1.0);
}
