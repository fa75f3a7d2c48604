attribute vec4 a_position;
uniform float u_k[gl_MaxFragmentUniformVectors];
void main() {
  gl_Position = a_position * u_k[0];
}
