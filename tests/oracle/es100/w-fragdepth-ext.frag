#extension GL_EXT_frag_depth : enable
precision mediump float;
void main() {
  gl_FragDepthEXT = 0.5;
  gl_FragColor = vec4(1.0);
}
