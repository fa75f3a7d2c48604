#version 300 es
in vec4 a_arr[2];
void main() {
  gl_Position = a_arr[1];
}
