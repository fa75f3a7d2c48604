#version 300 es
// One step of the particles, captured by transform feedback (INTERLEAVED_ATTRIBS: v_position,
// v_velocity): a spring towards the centre, a tangential push and a little drag; explicit
// Euler, no branch, so that nothing turns on the last bit of a float.
layout(location = 0) in vec2 a_position;
layout(location = 1) in vec2 a_velocity;
uniform float u_dt;
out vec2 v_position;
out vec2 v_velocity;
void main() {
  vec2 p = a_position;
  vec2 acceleration = -1.5 * p + 0.9 * vec2(-p.y, p.x) - 0.4 * a_velocity;
  v_velocity = a_velocity + u_dt * acceleration;
  v_position = p + u_dt * v_velocity;
}
