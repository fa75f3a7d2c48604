#version 300 es
// A full-screen triangle from gl_VertexID, moved by a uniform that only this stage uses.
uniform vec2 u_offset;
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID & 2) * 2 - 1));
  gl_Position = vec4(p + u_offset, 0.0, 1.0);
}
