#version 300 es
// Corrected twin of phong-directional.frag (article 002): `**` (markdown damage) -> `*` (4 occurrences).
// Numerical fix (essl-lint pow-zero-base): the exponent `max(uShininess, 1e-4)`: pow(0, 0) is undefined
// (NaN) where the highlight's base is 0, should the shininess be set to 0; no other value changes.
precision mediump float;
uniform float uShininess;
uniform vec3 uLightDirection;
uniform vec4 uLightAmbient;
uniform vec4 uLightDiffuse;
uniform vec4 uLightSpecular;
uniform vec4 uMaterialAmbient;
uniform vec4 uMaterialDiffuse;
uniform vec4 uMaterialSpecular;

in vec3 vNormal;
in vec3 vEyeVector;

out vec4 fragColor;

void main(void) {
  vec3 L = normalize(uLightDirection);
  vec3 N = normalize(vNormal);

  float lambertTerm = dot(N, -L);

  vec4 Ia = uLightAmbient * uMaterialAmbient;

  vec4 Id = vec4(0.0, 0.0, 0.0, 1.0);
  vec4 Is = vec4(0.0, 0.0, 0.0, 1.0);

  if (lambertTerm > 0.0) {
    Id = uLightDiffuse * uMaterialDiffuse * lambertTerm;
    vec3 E = normalize(vEyeVector);
    vec3 R = reflect(L, N);
    float specular = pow( max(dot(R, E), 0.0), max(uShininess, 1e-4));
    Is = uLightSpecular * uMaterialSpecular * specular;
  }
  fragColor = vec4(vec3(Ia + Id + Is), 1.0);
}
