#version 300 es
// Uses every derived value so that all are active uniforms (essl-scene test scenes).
in vec4 a_position;
in vec3 a_normal;
in vec2 a_uv;
uniform mat4 u_mvp;
uniform mat4 u_model;
uniform mat4 u_view;
uniform mat4 u_projection;
uniform mat4 u_view_projection;
uniform mat4 u_model_view;
uniform mat4 u_mit;
uniform mat3 u_normal3;
uniform mat4 u_normal4;
uniform vec3 u_eye;
uniform vec2 u_viewport;
out vec3 v_n;
out vec2 v_uv;
void main() {
  vec4 p = u_mvp * a_position;
  p += 1e-30 * (u_model * a_position + u_view * a_position + u_projection * a_position
                + u_view_projection * a_position + u_model_view * a_position + u_mit * a_position
                + u_normal4 * a_position + vec4(u_eye, 0.0) + vec4(u_viewport, 0.0, 0.0));
  gl_Position = p;
  v_n = u_normal3 * a_normal;
  v_uv = a_uv;
}
