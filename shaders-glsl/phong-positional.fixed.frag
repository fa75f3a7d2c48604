#version 300 es
// Corrected twin of phong-positional.frag (article 002): `**` (markdown damage) -> `*` (4 occurrences).
// Numerical fix (essl-lint pow-zero-base): the exponent `max(uShininess, 1e-4)`: pow(0, 0) is undefined
// (NaN) where the highlight's base is 0, should the shininess be set to 0; no other value changes.

precision highp float;

uniform vec4 uMaterialDiffuseColor;
uniform vec4 uMaterialSpecularColor;
uniform vec4 uMaterialAmbientColor;
uniform vec4 uLightDiffuseColor;
uniform vec4 uLightAmbientColor;
uniform vec4 uLightSpecularColor;
uniform float uShininess;

in vec3 vNormal;
in vec3 vLightRay;
in vec3 vEyeVector;

out vec4 fragColor;

void main(void) {
  vec3 L = normalize(vLightRay);
  vec3 N = normalize(vNormal);

  vec4 Ia = uMaterialAmbientColor * uLightAmbientColor;
  vec4 Id = vec4(0.0, 0.0, 0.0, 1.0);
  vec4 Is = vec4(0.0, 0.0, 0.0, 1.0);
  float lambertTerm = dot(N, -L);

  if (lambertTerm > 0.0) {
    Id = uLightDiffuseColor * uMaterialDiffuseColor * lambertTerm;
    vec3 E = normalize(vEyeVector);
    vec3 R = reflect(L, N);
    float specular = pow(max(dot(R, E), 0.0), max(uShininess, 1e-4));
    Is = uLightSpecularColor * uMaterialSpecularColor * specular;
  }

  fragColor = vec4(vec3(Ia + Id + Is), 1.0);
}
