#version 300 es
// Corrected twin of phong-directional.vert (article 002): `**` (markdown damage) -> `*`
// (2 occurrences, the gl_Position line that spans two lines).
precision mediump float;
uniform mat4 uModelViewMatrix;
uniform mat4 uProjectionMatrix;
uniform mat4 uNormalMatrix;

in vec3 aVertexPosition;
in vec3 aVertexNormal;

out vec3 vNormal;
out vec3 vEyeVector;

void main(void) {
  vec4 vertex = uModelViewMatrix * vec4(aVertexPosition, 1.0);
  vNormal = vec3(uNormalMatrix * vec4(aVertexNormal, 1.0));
  // Eye vector -> vector between camera and vector
  vEyeVector = -vec3(vertex.xyz);
  gl_Position = uProjectionMatrix * uModelViewMatrix *
  vec4(aVertexPosition, 1.0);
}
