#version 300 es
// Uses every kind of scene uniform value (essl-scene test scenes).
precision highp float;
in vec3 v_n;
in vec2 v_uv;
uniform float u_cos;
uniform vec3 u_dir;
uniform bool u_flag;
uniform ivec2 u_ivec;
uniform uint u_count;
uniform float u_arr[3];
uniform vec4 u_color;
uniform sampler2D u_tex_b;
uniform sampler2D u_tex_a;
out vec4 color;
void main() {
  float k = u_cos + dot(u_dir, normalize(v_n + vec3(0.0, 0.0, 1e-3))) + u_arr[0] + u_arr[1] + u_arr[2]
            + float(u_ivec.x + u_ivec.y) + float(u_count);
  color = u_color * (u_flag ? 1.0 : 0.5) + 1e-3 * k + texture(u_tex_a, v_uv) * texture(u_tex_b, v_uv);
}
