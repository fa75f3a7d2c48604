precision mediump float;
varying vec3 a[10];
varying vec2 b[20];
varying float c[30];
varying vec4 d[5];
void main() {
  gl_FragColor = vec4(a[9].x + b[19].x + c[29] + d[4].x);
}
