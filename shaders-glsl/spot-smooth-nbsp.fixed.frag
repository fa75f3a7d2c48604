#version 300 es  
// Corrected twin of spot-smooth-nbsp.frag (article 000), minimal fixes only:
//  1. every U+00A0 no-break space (version line, comments, indentation) -> ASCII space;
//  2. `uniform float u_innerLimit` -> add the missing `;`;
//  3. `float dotFromDirection = dot(unitSurfaceToLight, -u_lightDirection)` -> add the missing `;`.
//  4. numerics (essl-lint smoothstep-edges): `smoothstep(u_outerLimit, u_innerLimit, …)` is
//     undefined when the limits are equal or swapped -> edge1 kept above edge0 with
//     `max(u_innerLimit, u_outerLimit + 1e-4)`.
// The first line keeps its trailing space(s) from the replaced NBSP.
// Numerical fix (essl-lint pow-zero-base): the exponent `max(u_shininess, 1e-4)`: pow(0, 0) is undefined
// (NaN) where the highlight's base is 0, should the shininess be set to 0; no other value changes.
  
// fragment shaders don't have a default precision so we need  
// to pick one. highp is a good default. It means "high precision"  
precision highp float;
  
// Passed in and varied from the vertex shader.
in vec3 v_normal;
in vec3 v_surfaceToLight;
in vec3 v_surfaceToView;
  
uniform vec4 u_color;
uniform float u_shininess;
uniform vec3 u_lightColor;
uniform vec3 u_specularColor;
  
// Spotlight limit
uniform vec3 u_lightDirection;
uniform float u_innerLimit;
uniform float u_outerLimit;
  
// We need to declare an output for the fragment shader  
out vec4 outColor;

void main() {


  // Varyings that are unit verctos are interpolated
  // so they will not be a unit vector. Normalizing the
  // will make them unit vectors again
  vec3 normal = normalize(v_normal);
  vec3 unitSurfaceToLight = normalize(v_surfaceToLight);

  vec3 unitSurfaceToView = normalize(v_surfaceToView);
  vec3 halfVector = normalize(unitSurfaceToLight + unitSurfaceToView);
  
  // compute light and specularity

  float dotFromDirection = dot(unitSurfaceToLight, -u_lightDirection);
  
  float inLight = smoothstep(u_outerLimit, max(u_innerLimit, u_outerLimit + 1e-4), dotFromDirection);
  
  float light = inLight * dot(normal, unitSurfaceToLight);
  float rawSpecular = max(0.0, dot(normal, halfVector));
  float specular = pow(rawSpecular, max(u_shininess, 1e-4));
  float limitedSpecular = step(0.1, light) * specular;
  
  // Apply color
  outColor = u_color;
  
  // Lets multiply just the color portion (not the alpha)
  // by the light
  outColor.rgb *= light * u_lightColor;
  
  // Just add in the specular
  outColor.rgb += limitedSpecular * u_specularColor;
}
