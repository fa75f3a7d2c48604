#version 300 es
// Outputs for transform feedback: a vec4 and a float computed from the vertex id and a_value.
layout(location = 0) in float a_value;
out vec4 v_vector;
out float v_scalar;
void main() {
  float i = float(gl_VertexID);
  v_vector = vec4(i, a_value, i * a_value, 1.0);
  v_scalar = a_value * 0.5;
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
