#version 300 es
// One triangle that covers the viewport, from gl_VertexID alone (drawArrays(TRIANGLES, 0, 3)
// with no attributes): clip positions (-1, -1), (3, -1), (-1, 3).
out vec2 v_uv;
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
  v_uv = p * 0.5 + 0.5;
  gl_Position = vec4(p, 0.0, 1.0);
}
