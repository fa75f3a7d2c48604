#extension GL_EXT_shader_texture_lod : enable
precision mediump float;
uniform sampler2D s;
uniform samplerCube c;
void main() {
  gl_FragColor = texture2DLodEXT(s, vec2(0.5), 1.0) + textureCubeGradEXT(c, vec3(1.0), vec3(0.0), vec3(0.0)) + texture2DProjLodEXT(s, vec4(1.0), 0.0);
}
