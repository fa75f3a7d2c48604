precision mediump float;
varying mat3 v0;
varying mat3 v1;
varying mat3 v2;
varying mat3 v3;
varying mat3 v4;
varying mat3 v5;
varying mat3 v6;
varying mat3 v7;
varying mat3 v8;
varying mat3 v9;
varying mat3 v10;
void main() {
  vec4 s = vec4(0.0);
  s.x += v0[0][0];
  s.x += v1[0][0];
  s.x += v2[0][0];
  s.x += v3[0][0];
  s.x += v4[0][0];
  s.x += v5[0][0];
  s.x += v6[0][0];
  s.x += v7[0][0];
  s.x += v8[0][0];
  s.x += v9[0][0];
  s.x += v10[0][0];
  gl_FragColor = s;
}
