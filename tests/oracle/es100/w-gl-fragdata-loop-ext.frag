#extension GL_EXT_draw_buffers : require
precision mediump float;
void main() {
  for (int i = 0; i < 2; i++) {
    gl_FragData[i] = vec4(1.0);
  }
}
