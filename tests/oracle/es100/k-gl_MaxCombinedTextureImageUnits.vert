attribute vec4 a_position;
uniform float u_k[gl_MaxCombinedTextureImageUnits];
void main() {
  gl_Position = a_position * u_k[0];
}
