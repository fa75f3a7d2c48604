#version 300 es
void main() {
  gl_Position = vec4(float(gl_VertexID), float(gl_InstanceID), 0.0, 1.0);
}
