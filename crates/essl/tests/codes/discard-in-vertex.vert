#version 300 es
void main() {
  discard;
  gl_Position = vec4(0.0);
}
