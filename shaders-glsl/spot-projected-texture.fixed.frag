#version 300 es
// CORRECTED twin of spot-projected-texture.frag (article 003 composed into a shader): the
// same code with the numerical hazards essl lint reports removed, each change marked `fixed`:
//   - smoothstep with ordered edges (equal or swapped edges are undefined);
//   - acos of clamped cosines (rounding pushes dot products of unit vectors past ±1: NaN);
//   - the left vector from a cross product scaled by a guarded inverse length instead of
//     `normalize` (the up vector parallel to the direction makes it zero: NaN).
precision highp float;

#define NUM_SPOT_LIGHTS 1 // added
#define PI 3.141592653589793 // added

struct SpotLight {
vec3 position;
vec3 direction;
vec3 color;
float distance;
float decay;
float coneCos;
float penumbraCos;
};

uniform SpotLight spotLights[ NUM_SPOT_LIGHTS ];

struct SpotLightEx {
vec3 up;
float intensity;
};

uniform sampler2D spotLightTextures[ NUM_SPOT_LIGHTS ];
uniform SpotLightEx spotLightExs[ NUM_SPOT_LIGHTS ];

// added: three.js's GeometricContext and IncidentLight, reduced to what is used
struct GeometricContext {
  vec3 position;
  vec3 normal;
};

struct IncidentLight {
  vec3 color;
  vec3 direction;
  bool visible;
};

// added: three.js's cone and distance attenuation
float getSpotAttenuation( const in float coneCosine, const in float penumbraCosine, const in float angleCosine ) {
  return smoothstep( coneCosine, max( penumbraCosine, coneCosine + 1e-4 ), angleCosine ); // fixed: ordered edges
}

float getDistanceAttenuation( const in float lightDistance, const in float cutoffDistance, const in float decayExponent ) {
  if ( cutoffDistance > 0.0 && decayExponent > 0.0 ) {
    return pow( clamp( - lightDistance / cutoffDistance + 1.0, 0.0, 1.0 ), decayExponent );
  }
  return 1.0;
}

// added: the snippets name the current light's extras `spotLightEx` and `spotLightTexture`;
// with one spot light they are element 0 of the uniform arrays (a constant index, as
// GLSL ES 3.00 requires for arrays of samplers)
#define spotLightEx spotLightExs[ 0 ]
#define spotLightTexture spotLightTextures[ 0 ]

void getSpotLightInfo( const in SpotLight spotLight, const in GeometricContext geometry, out IncidentLight light ) {
vec3 lVector = spotLight.position - geometry.position;
light.direction = normalize( lVector );
float angleCos = dot( light.direction, spotLight.direction );
float spotAttenuation = getSpotAttenuation( spotLight.coneCos, spotLight.penumbraCos, angleCos );
if ( spotAttenuation > 0.0 ) {
float lightDistance = length( lVector );

// ---
// Here the fragment is being lit by the spotlight
// Instead of spotLight.color, the color needs to come from the texture
// ---
vec2 samplePoint; // added
vec3 color; // added

// Convert the cone angle cosine back into radians
float coneAngle = acos(clamp(spotLight.coneCos, -1.0, 1.0)); // fixed: clamped

// Get the cosine between the light ray and the up vector
float upCos = dot(light.direction, spotLightEx.up);
// Convert to radians
float upAngle = acos(clamp(upCos, -1.0, 1.0)); // fixed: clamped

// Calculate the y coordinate of the sample point
// The PI/2.0 (= 90°) is compensation for the 90° between spotlight direction and up vector
// The coneAngle extends in both directions from the center, hence the 2.0 * coneAngle
// Shift the resulting [-0.5, 0.5] range by 0.5 to get [0.0, 1.0]
samplePoint.y = 0.5	+ (upAngle - PI/2.0) / (2.0 * coneAngle);

// Compute a left vector from the up vector and the spotlight direction
// fixed: scaled by a guarded inverse length (0 instead of NaN when up is parallel to the
// direction, which centres the image on that axis)
vec3 across = cross(spotLightEx.up, spotLight.direction);
vec3 left = across * inversesqrt(max(dot(across, across), 1e-24));

// Get the cosine between the light ray and the up vector
float leftCos = dot(light.direction, left);
// Convert to radians
float leftAngle = acos(clamp(leftCos, -1.0, 1.0)); // fixed: clamped

// Calculate the x coordinate of the sample point
samplePoint.x = 0.5 + (leftAngle - PI/2.0) / (2.0 * coneAngle);

color = texture(spotLightTexture, samplePoint).rgb * spotLightEx.intensity; // essl-allow: non-uniform-derivative (numerics only: the article's lookup under `if (spotAttenuation > 0.0)` is kept)

light.color = spotLight.color * spotAttenuation;
light.color *= color; // added: the light takes the projected texture's colour
light.color *= getDistanceAttenuation( lightDistance, spotLight.distance, spotLight.decay );
light.visible = ( light.color != vec3( 0.0 ) );
} else {
light.color = vec3( 0.0 );
light.visible = false;
}
}

// added: view-space position and normal from the vertex shader, a Lambert term, main()
in vec3 v_viewPosition;
in vec3 v_normal;

out vec4 outColor;

void main() {
  GeometricContext geometry;
  geometry.position = v_viewPosition;
  geometry.normal = normalize( v_normal );
  IncidentLight light;
  getSpotLightInfo( spotLights[ 0 ], geometry, light );
  float lambert = max( dot( geometry.normal, light.direction ), 0.0 );
  outColor = vec4( light.visible ? light.color * lambert : vec3( 0.0 ), 1.0 );
}
