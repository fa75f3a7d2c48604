#version 300 es
// Particles as 9-pixel points, coloured by speed.
layout(location = 0) in vec2 a_position;
layout(location = 1) in vec2 a_velocity;
out vec3 v_color;
void main() {
  float speed = clamp(length(a_velocity) * 1.5, 0.0, 1.0);
  v_color = mix(vec3(0.2, 0.45, 1.0), vec3(1.0, 0.55, 0.15), speed);
  gl_Position = vec4(0.85 * a_position, 0.0, 1.0);
  gl_PointSize = 9.0;
}
