#version 300 es
out vec4 v;
void main() {
  invariant v;
  v = vec4(1.0);
  gl_Position = v;
}
