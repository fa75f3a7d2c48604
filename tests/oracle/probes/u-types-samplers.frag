#version 300 es
precision mediump float;
out vec4 o;
precision highp sampler3D;
precision highp sampler2DShadow;
precision highp isampler2D;
precision highp usampler2D;
precision highp sampler2DArray;
uniform sampler2D u_s2d;
uniform samplerCube u_cube;
uniform sampler3D u_s3d;
uniform sampler2DShadow u_shadow;
uniform isampler2D u_is2d;
uniform usampler2D u_us2d;
uniform sampler2DArray u_s2da;
void main() {
  o = texture(u_s2d, vec2(0.5)) + texture(u_cube, vec3(1.0)) + texture(u_s3d, vec3(0.5));
  o += vec4(texture(u_shadow, vec3(0.5)));
  o += vec4(texture(u_is2d, vec2(0.5))) + vec4(texture(u_us2d, vec2(0.5)));
  o += texture(u_s2da, vec3(0.5));
}
