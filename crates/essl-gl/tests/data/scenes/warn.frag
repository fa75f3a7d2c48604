#version 300 es
// essl-gl scene test: uniforms that are inactive or not set, a sampler that is unused.
precision mediump float;
in vec3 v_n;
in vec4 v_color;
uniform vec3 u_light;
uniform float u_unused;
uniform vec4 u_tint;
uniform sampler2D u_never;
uniform sampler2D u_tex;
out vec4 color;
void main() {
  float d = max(dot(normalize(v_n), u_light), 0.0);
  color = vec4(d * (v_color.rgb + vec3(0.6, 0.5, 0.2)), 1.0) + u_tint + 0.25 * texture(u_tex, v_n.xy * 0.5 + 0.5);
}
