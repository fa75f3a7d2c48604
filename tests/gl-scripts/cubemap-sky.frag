#version 300 es
// The background of the final picture: the cube map seen along the view direction.
precision highp float;
uniform samplerCube u_environment;
uniform mat4 u_inverseViewProjection;
uniform vec3 u_eye;
in vec2 v_uv;
out vec4 o_color;
void main() {
  vec4 far = u_inverseViewProjection * vec4(v_uv * 2.0 - 1.0, 1.0, 1.0);
  o_color = vec4(texture(u_environment, far.xyz / far.w - u_eye).rgb, 1.0);
}
