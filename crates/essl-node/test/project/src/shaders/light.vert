#version 300 es
in vec4 a_position;
in vec3 a_normal;
uniform mat4 u_worldViewProjection;
uniform mat3 u_normalMatrix;
out vec3 v_normal;
void main() {
  gl_Position = u_worldViewProjection * a_position;
  v_normal = u_normalMatrix * a_normal;
}
