#version 300 es
// An unsigned-integer attribute (uvec4) at location 0.
layout(location = 0) in uvec4 a_id;
flat out uint v_id;
void main() {
  v_id = a_id.x;
  gl_Position = vec4(float(gl_VertexID & 1) * 4.0 - 1.0, float(gl_VertexID & 2) * 2.0 - 1.0, 0.0, 1.0);
}
