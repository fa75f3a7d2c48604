#version 300 es
// CORRECTED twin of spot-flashlight-cookie.frag (article 004 composed into a shader): the
// same code with the division by `epsilon = light.cutOff - light.outerCutOff` guarded, as
// essl lint asks (equal cut-offs divide by zero), marked `fixed`.
// Numerical fix (essl-lint pow-zero-base): the exponent `max(material.shininess, 1e-4)`: pow(0, 0) is undefined
// (NaN) where the highlight's base is 0, should the shininess be set to 0; no other value changes.
precision highp float;

struct Material {
    sampler2D diffuse;
    sampler2D specular;
    float shininess;
};

struct Light {
    vec3 position;
    vec3 direction;
    float cutOff;
    float outerCutOff;

    vec3 ambient;
    vec3 diffuse;
    vec3 specular;

    sampler2D flashlight;
};

in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;

out vec4 FragColor;

uniform vec3 viewPos;
uniform Material material;
uniform Light light;
uniform vec2 viewPort;

void main()
{
    // ambient
    vec3 ambient = light.ambient * texture(material.diffuse, TexCoords).rgb;

    // diffuse
    vec3 norm = normalize(Normal);
    vec3 lightDir = normalize(light.position - FragPos);
    float diff = max(dot(norm, lightDir), 0.0);
    vec3 diffuse = light.diffuse * diff * texture(material.diffuse, TexCoords).rgb;

    // specular
    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 reflectDir = reflect(-lightDir, norm);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), max(material.shininess, 1e-4));
    vec3 specular = light.specular * spec * texture(material.specular, TexCoords).rgb;

    // spotlight (soft edges) and flashlight cookie: verbatim from the article
float theta = dot(lightDir, normalize(-light.direction));
float epsilon = max(light.cutOff - light.outerCutOff, 1e-4); // fixed: never 0
float intensity = clamp((theta - light.outerCutOff) / epsilon, 0.0, 1.0);
vec2 fragCoord = gl_FragCoord.xy / viewPort * vec2(1.0, -1.0);
intensity *= length(vec3(texture(light.flashlight, fragCoord)));
// we'll leave ambient unaffected so we always have a little light.
diffuse *= intensity;
specular *= intensity;

    FragColor = vec4(ambient + diffuse + specular, 1.0);
}
