#version 300 es
precision mediump float;
out vec4 o;
struct S0 {
  float x;
};
struct S1 {
  S0 s;
};
struct S2 {
  S1 s;
};
struct S3 {
  S2 s;
};
struct S4 {
  S3 s;
};
void main() {
  o = vec4(1.0);
}
