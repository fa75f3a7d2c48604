#version 300 es
// Corrected twin of gouraud-phong.vert (article 002), minimal fixes only:
//  1. `**` (markdown damage) -> `*` (4 lines);
//  2. undeclared `uMaterialDiffuse` -> `uniform vec4 uMaterialDiffuse;` added;
//  3. undeclared `shininess` -> `uniform float shininess;` added;
//  4. undeclared `vectex` -> `vec4 vertex = uModelViewMatrix * vec4(aVertexPosition, 1.0);`
//     added and `vectex` spelled `vertex`;
//  5. undeclared `lightReflection` -> `vec3 lightReflection = reflect(L, N);` added;
//  6. `Id`, `Is` were declared inside the `if` but used after it -> declared before the `if`
//     as `vec4(0.0)` and assigned inside it.
// Numerical fix (essl-lint pow-zero-base): the exponent `max(shininess, 1e-4)`: pow(0, 0) is undefined
// (NaN) where the highlight's base is 0, should the shininess be set to 0; no other value changes.
precision mediump float;
uniform mat4 uModelViewMatrix;
uniform mat4 uProjectionMatrix;
uniform mat4 uNormalMatrix;
// Light and materials
uniform vec3 uLightDirection;
uniform vec4 uLightAmbient;
uniform vec4 uLightDiffuse;
uniform vec4 uLightSpecular;
uniform vec4 uMaterialDiffuse;
uniform float shininess;

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
  vec4 vertex = uModelViewMatrix * vec4(aVertexPosition, 1.0);
  vec3 eyeVector = -vertex.xyz;

  // Ambient colors
  vec4 Ia = uMaterialDiffuse * uLightAmbient;
  float lambertTerm = dot(N,-L);
  vec4 Id = vec4(0.0);
  vec4 Is = vec4(0.0);
  // If this value is positive the cos between the surface normal and the negative light direction is positive, that is the angle is between 0º and 90º or between 270º and 360º
  // which means the surface is facing the light
  if (lambertTerm > 0.0) {
    // Diffuse colors
    Id = uMaterialDiffuse * uLightDiffuse * lambertTerm;
    vec3 lightReflection = reflect(L, N);
    // Specular colors: note we retrieve the positive value for the dot product between R and E
    float specular = pow(max(dot(lightReflection, eyeVector), 0.0), max(shininess, 1e-4));
    Is = uMaterialDiffuse * uLightSpecular * specular;
  }

  // Combine ambient and diffuse
  vVertexColor = vec4(vec3(Ia + Id + Is), 1.0);

  gl_Position = uProjectionMatrix * uModelViewMatrix * vec4(aVertexPosition, 1.0);
}
