#version 300 es
// Green where every uniform holds the value the test uploads through the generated bindings,
// red where one does not; the two samplers' texels go to the blue channel's test.
precision highp float;
precision highp int;

struct Light {
  vec3 position;
  float cutoff;
  bool on;
};

struct Rig {
  Light lights[2];
  mat3x2 warp;
  ivec2 cells;
};

uniform Light u_light;
uniform Light u_lights[3];
uniform Rig u_rig;
uniform bvec3 u_flags;
uniform bool u_switches[2];
uniform uvec4 u_mask;
uniform int u_counts[3];
uniform mat2 u_turns[2];
uniform mat4x3 u_frame;
uniform vec4 u_colors[2];
uniform float type;
uniform sampler2D u_textures[2];

// A block with an instance name, holding a struct, an array, a matrix and a bvec.
layout(std140) uniform Material {
  Light key;
  vec2 uvs[3];
  mat3 basis;
  bvec2 bits;
  uint tag;
} material;

out vec4 color;

bool same(vec3 a, vec3 b) { return all(equal(a, b)); }

void main() {
  bool ok = same(u_light.position, vec3(1.0, 2.0, 3.0)) && u_light.cutoff == 0.5 && u_light.on;
  for (int i = 0; i < 3; i++) {
    float f = float(i);
    ok = ok && same(u_lights[i].position, vec3(f, f + 0.25, -f)) && u_lights[i].cutoff == f * 0.125
         && u_lights[i].on == (i != 1);
  }
  ok = ok && same(u_rig.lights[1].position, vec3(7.0, 8.0, 9.0)) && !u_rig.lights[0].on;
  ok = ok && u_rig.warp[2] == vec2(5.0, 6.0) && u_rig.warp[0] == vec2(1.0, 2.0);
  ok = ok && u_rig.cells == ivec2(-3, 4);
  ok = ok && u_flags == bvec3(true, false, true) && u_switches[0] == false && u_switches[1];
  ok = ok && u_mask == uvec4(1u, 0xffffffffu, 3u, 4u);
  ok = ok && u_counts[0] == -1 && u_counts[2] == 2147483647;
  ok = ok && u_turns[1][0] == vec2(0.0, 1.0) && u_turns[1][1] == vec2(-1.0, 0.0) && u_turns[0][0].x == 2.0;
  ok = ok && u_frame[3] == vec3(10.0, 11.0, 12.0) && u_frame[0] == vec3(1.0, 2.0, 3.0);
  ok = ok && u_colors[1] == vec4(0.25, 0.5, 0.75, 1.0) && type == -2.5;
  ok = ok && same(material.key.position, vec3(-1.0, -2.0, -3.0)) && material.key.cutoff == 0.75
       && material.key.on;
  ok = ok && material.uvs[0] == vec2(0.5, 1.5) && material.uvs[2] == vec2(4.5, 5.5);
  ok = ok && material.basis[1] == vec3(4.0, 5.0, 6.0) && material.basis[2][2] == 9.0;
  ok = ok && material.bits == bvec2(false, true) && material.tag == 77u;
  vec4 a = texture(u_textures[0], vec2(0.5));
  vec4 b = texture(u_textures[1], vec2(0.5));
  ok = ok && a.r > 0.9 && b.g > 0.9;
  color = ok ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0);
}
