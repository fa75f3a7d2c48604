#version 300 es
precision mediump float;
out vec4 o;
#define E0 E1 E1 E1 E1
#define E1 E2 E2 E2 E2
#define E2 E3 E3 E3 E3
#define E3 E4 E4 E4 E4
#define E4 E5 E5 E5 E5
#define E5 E6 E6 E6 E6
#define E6 E7 E7 E7 E7
#define E7 ;
void main() {
  E0
  o = vec4(1.0);
}
