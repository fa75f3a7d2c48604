#version 300 es
// Corrected twin of spot-diff.frag (article 001, the diff as published): the diff applied.
//  1. the line marked `-` (`float light = dot(normal, surfaceToLightDirection);`) removed;
//  2. the `+` and `*` markers at line starts removed (the rest of each line kept as is,
//     so some lines start with a space).
//  3. numerics (essl-lint pow-negative-base): `pow(max(dot(normal, halfVector), 0.0), u_shininess)`:
//     pow is undefined (NaN) for a negative base, and dot(normal, halfVector) < 0 is possible
//     even where `light > 0.0`.
// This is the article's `if (dotFromDirection >= u_limit)` spot light with one limit.
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
uniform float u_limit; // in dot space
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
 float light = 0.0;
float specular = 0.0;
 float dotFromDirection = dot(surfaceToLightDirection,
 -u_lightDirection);
 if (dotFromDirection >= u_limit) {
 light = dot(normal, surfaceToLightDirection);
 if (light > 0.0) {
 specular = pow(max(dot(normal, halfVector), 0.0), max(u_shininess, 1e-4));
 }
 }
outColor = u_color;
// Lets multiply just the color portion (not the alpha)
// by the light
outColor.rgb *= light;
// Just add in the specular
outColor.rgb += specular;
}
