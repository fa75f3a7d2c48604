#version 300 es
// essl-gl scene test: attributes that are inactive or not fed, a mat3 set from a 4x4 matrix.
in vec4 a_position;
in vec3 a_normal;
in vec4 a_color;
in vec2 a_unused;
uniform mat4 u_mvp;
uniform mat3 u_normal;
out vec3 v_n;
out vec4 v_color;
void main() {
  gl_Position = u_mvp * a_position;
  v_n = u_normal * a_normal;
  v_color = a_color;
}
