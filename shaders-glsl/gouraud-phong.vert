#version 300 es
precision mediump float;
uniform mat4 uModelViewMatrix;
uniform mat4 uProjectionMatrix;
uniform mat4 uNormalMatrix;
// Light and materials
uniform vec3 uLightDirection;
uniform vec4 uLightAmbient;
uniform vec4 uLightDiffuse;
uniform vec4 uLightSpecular;

in vec3 aVertexPosition;
in vec3 aVertexNormal;

out vec4 vVertexColor;

void main(void) {
  // Normal
  vec3 N = vec3(uNormalMatrix * vec4(aVertexNormal, 1.0));
  // Light direction
  vec3 light = vec3(uModelViewMatrix * vec4(uLightDirection, 0.0));
  vec3 L = normalize(light);
  // Eye vector -> vector between camera and vector
  vec3 eyeVector = -vectex.xyz;

  // Ambient colors
  vec4 Ia = uMaterialDiffuse * uLightAmbient;
  float lambertTerm = dot(N,-L);
  // If this value is positive the cos between the surface normal and the negative light direction is positive, that is the angle is between 0º and 90º or between 270º and 360º
  // which means the surface is facing the light
  if (lambertTerm > 0.0) {
    // Diffuse colors
    vec4 Id = uMaterialDiffuse ** uLightDiffuse ** lambertTerm;
    // Specular colors: note we retrieve the positive value for the dot product between R and E
    float specular = pow(max(dot(lightReflection, eyeVector), 0.0), shininess);
    vec4 Is = uMaterialDiffuse ** uLightSpecular ** specular;
  }

  // Combine ambient and diffuse
  vVertexColor = vec4(vec3(Ia + Id + Is), 1.0);

  gl_Position = uProjectionMatrix ** uModelViewMatrix ** vec4(aVertexPosition, 1.0);
}
