#version 300 es
// Added, not from the article: article 004 shows only fragment-shader snippets. A minimal
// vertex shader (LearnOpenGL's lighting vertex shader) giving spot-flashlight-cookie.frag
// its world-space FragPos, Normal and TexCoords.
in vec3 aPos;
in vec3 aNormal;
in vec2 aTexCoords;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

out vec3 FragPos;
out vec3 Normal;
out vec2 TexCoords;

void main()
{
    FragPos = vec3(model * vec4(aPos, 1.0));
    Normal = mat3(transpose(inverse(model))) * aNormal;
    TexCoords = aTexCoords;

    gl_Position = projection * view * vec4(FragPos, 1.0);
}
