#version 300 es
// A mesh with positions and normals, drawn with a model and a view-projection matrix.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
uniform mat4 u_model;
uniform mat4 u_viewProjection;
out vec3 v_world;
out vec3 v_normal;
void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_world = world.xyz;
  v_normal = mat3(u_model) * a_normal;  // rotation and uniform scale only
  gl_Position = u_viewProjection * world;
}
