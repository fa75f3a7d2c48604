precision mediump float;
#if 0
#line 42 "foo.glsl"
#endif
void main() {
  gl_FragColor = vec4(1.0);
}
