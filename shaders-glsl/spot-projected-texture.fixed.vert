#version 300 es
// Added, not from the article: article 003 shows only fragment-shader snippets. A minimal
// vertex shader giving spot-projected-texture.frag its view-space position and normal
// (three.js computes lights in camera space).
in vec4 a_position;
in vec3 a_normal;

uniform mat4 u_modelView;
uniform mat4 u_projection;
uniform mat3 u_normalMatrix;

out vec3 v_viewPosition;
out vec3 v_normal;

void main() {
  vec4 viewPosition = u_modelView * a_position;
  v_viewPosition = viewPosition.xyz;
  v_normal = u_normalMatrix * a_normal;
  gl_Position = u_projection * viewPosition;
}
