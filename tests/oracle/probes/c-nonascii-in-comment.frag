#version 300 es
precision mediump float;
out vec4 o;
// 90° ’quoted’ — dash
void main() {
  o = vec4(1.0);
}
