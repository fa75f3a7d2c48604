#version 300 es
// Variant of article 001 (not a block of the article): spot-step.frag with the article's
// second diff applied (its `+`/`-` markers removed): `u_limit` -> `u_innerLimit`/`u_outerLimit`,
// `inLight = clamp((dotFromDirection - u_outerLimit) / limitRange, 0.0, 1.0)`.
// Numerical fix (essl-lint pow-negative-base): `pow(max(dot(normal, halfVector), 0.0), u_shininess)`;
// pow is undefined (NaN) for a negative base, and dot(normal, halfVector) < 0 where the surface
// faces away from the half vector, even where dot(normal, surfaceToLight) > 0.
// Numerical fix (essl-lint division-by-difference): `limitRange = max(u_innerLimit - u_outerLimit, 1e-4)`;
// the article notes that equal limits divide by zero (a floor of 1e-4 stays normal in mediump).
// Numerical fix (essl-lint pow-zero-base): the exponent `max(u_shininess, 1e-4)`: pow(0, 0) is undefined
// (NaN) where the highlight's base is 0, should the shininess be set to 0; no other value changes.
precision mediump float;
// Passed in from the vertex shader.
in vec3 v_normal;
in vec3 v_surfaceToLight;
in vec3 v_surfaceToView;
uniform vec4 u_color;
uniform float u_shininess;
uniform vec3 u_lightDirection;
uniform float u_innerLimit; // in dot space
uniform float u_outerLimit; // in dot space
// we need to declare an output for the fragment shader
out vec4 outColor;
void main() {
// because v_normal is a varying it's interpolated
// so it will not be a unit vector. Normalizing it
// will make it a unit vector again
vec3 normal = normalize(v_normal);
vec3 surfaceToLightDirection = normalize(v_surfaceToLight);
vec3 surfaceToViewDirection = normalize(v_surfaceToView);
vec3 halfVector = normalize(surfaceToLightDirection + surfaceToViewDirection);
float dotFromDirection = dot(surfaceToLightDirection,
-u_lightDirection);
// inLight will be 1 if we're inside the spotlight and 0 if not
 float limitRange = max(u_innerLimit - u_outerLimit, 1e-4);
 float inLight = clamp((dotFromDirection - u_outerLimit) / limitRange, 0.0, 1.0);
float light = inLight * dot(normal, surfaceToLightDirection);
float specular = inLight * pow(max(dot(normal, halfVector), 0.0), max(u_shininess, 1e-4));
outColor = u_color;
// Lets multiply just the color portion (not the alpha)
// by the light
outColor.rgb *= light;
// Just add in the specular
outColor.rgb += specular;
}
