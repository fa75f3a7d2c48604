#version 300 es
// A full-screen triangle from gl_VertexID, moved by a uniform that only this stage uses.
uniform vec2 u_offset;
// A uniform block without an instance name, used by this stage only.
uniform Camera {
  mat4 u_view;
  vec3 u_eye;
  float u_scale;
};
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID & 2) * 2 - 1));
  // u_view is the identity, u_eye (0, 0, 1) and u_scale 1 when the block's bytes are right.
  vec4 moved = u_view * vec4(p + u_offset, 0.0, 1.0);
  gl_Position = vec4(moved.xy * u_scale, u_eye.z - 1.0, 1.0);
}
