#version 300 es
// Names that Rust reserves or that the bindings use themselves: the generated module (`match_`)
// must still compile. A struct named like a Rust type, a uniform `self`, an attribute `type`,
// an anonymous struct, and a struct name that the fragment shader defines differently.
struct f32 {
  float impl;
  int Self;
};
struct Light {
  vec3 position;
};
uniform f32 self;
uniform Light u_vertexLight;
uniform struct {
  float mod;
  bool ZERO;
} u_anonymous;
in vec4 type;
in vec2 a_uv;
out vec2 v_uv;
void main() {
  v_uv = a_uv * self.impl + float(self.Self) + u_vertexLight.position.xy;
  gl_Position = type * u_anonymous.mod * (u_anonymous.ZERO ? 1.0 : 2.0);
}
