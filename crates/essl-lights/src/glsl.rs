//! The library's GLSL building blocks: the stable formulations
//! (`docs/numerical-stability.md`), each the GLSL twin of a function in [`crate::formulas`]
//! (which the stiff-case matrix evaluates on the CPU). All names start with `el_`.

/// Unit vector of `v`, or zero when `v` is zero. Dividing by the largest component first keeps
/// `dot` in `[1, 3]`: no overflow above `1.8e19`, no underflow below `1e-19` (mediump: 256 and
/// 0.004), and `normalize(0)`'s `0 · inversesqrt(0) = NaN` cannot happen.
pub const NORMALIZE: &str = "\
// Unit vector of v, or zero when v is zero: scaled by its largest component first, so no
// intermediate over- or underflows at any scale.
vec3 el_normalize(vec3 v) {
  float m = max(max(abs(v.x), abs(v.y)), abs(v.z));
  vec3 s = v / max(m, 1.0e-30);
  return m > 0.0 ? s * inversesqrt(dot(s, s)) : vec3(0.0);
}
";

/// `max(x, 0)^n` with `0^0 = 1`: the base is clamped to `[2^-24, 1]`, so `pow` never sees a
/// negative base or `0^0` (both undefined in GLSL); for `n ≥ 1` the floor adds at most `6e-8`.
pub const POWER: &str = "\
// max(x, 0)^n with 0^0 = 1, for n = 0 or n >= 1: pow never sees a negative base or 0^0.
float el_power(float x, float n) {
  return pow(clamp(x, 5.9604645e-8, 1.0), n);
}
";

/// Diffuse only: `max(N·L, 0) · diffuse`.
pub const DIRECT_LAMBERT: &str = "\
// Light arriving from unit direction L: Lambert's max(N.L, 0) times the diffuse product.
vec3 el_direct(vec3 N, vec3 L, vec3 diffuse) {
  return max(dot(N, L), 0.0) * diffuse;
}
";

/// Diffuse plus Phong specular, both weighted by `max(N·L, 0)` (continuous at the terminator).
pub const DIRECT_PHONG: &str = "\
// Light arriving from unit direction L: max(N.L, 0) times diffuse plus Phong's specular
// max(R.V, 0)^n (the cosine weights the specular too, so nothing jumps at the terminator).
vec3 el_direct(vec3 N, vec3 L, vec3 V, vec3 diffuse, vec3 specular) {
  float s = el_power(dot(reflect(-L, N), V), u_shininess);
  return max(dot(N, L), 0.0) * (diffuse + s * specular);
}
";

/// Diffuse plus Blinn–Phong specular, both weighted by `max(N·L, 0)`.
pub const DIRECT_BLINN: &str = "\
// Light arriving from unit direction L: max(N.L, 0) times diffuse plus Blinn's specular
// max(N.H, 0)^n; H is zero (no highlight) when L = -V exactly.
vec3 el_direct(vec3 N, vec3 L, vec3 V, vec3 diffuse, vec3 specular) {
  float s = el_power(dot(N, el_normalize(L + V)), u_shininess);
  return max(dot(N, L), 0.0) * (diffuse + s * specular);
}
";

/// Linear edge: `clamp((d − cos outer) · invRange, 0, 1)`; the slope comes from the CPU
/// (never infinite), and `d − cos outer` is exact near the edge (Sterbenz).
pub const EDGE_LINEAR: &str = "\
// Linear spot edge in the cosine d: 0 at cos(outer), 1 at cos(inner). invRange is computed on
// the CPU and capped, so inner == outer is a step, never 0/0.
float el_edgeLinear(float d, float cosOuter, float invRange) {
  return clamp((d - cosOuter) * invRange, 0.0, 1.0);
}
";

/// Smooth edge: Hermite of the clamped linear ramp, written out (`smoothstep(a, b, x)` is
/// undefined for `a >= b`).
pub const EDGE_SMOOTH: &str = "\
// Smooth spot edge: t^2 (3 - 2t) of the linear ramp, written out because smoothstep(a, b, x)
// is undefined when a >= b.
float el_edgeSmooth(float d, float cosOuter, float invRange) {
  float t = clamp((d - cosOuter) * invRange, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}
";

/// Article 003's projector coordinates `0.5 + asin(q.xy) / (2 · cone)` as `atan`: defined for
/// every `q` (no `acos` of a dot rounded past ±1, no `cross` of parallel vectors).
pub const PROJECTOR_UV: &str = "\
// Texture coordinates of the unit direction q in the projector's frame (left, up, forward):
// article 003's 0.5 + (acos(dot) - pi/2) / (2 cone) written as atan of the components, defined
// for every q.
vec2 el_projectorUv(vec3 q, float scale) {
  float x = atan(q.x, max(length(q.yz), 1.0e-30));
  float y = atan(q.y, max(length(q.xz), 1.0e-30));
  return 0.5 + scale * vec2(x, y);
}
";

/// Screen-space cookie coordinates: `s` left to right, `t` top (0) to bottom (1), without
/// relying on `REPEAT` for a negative coordinate.
pub const SCREEN_UV: &str = "\
// Screen-space cookie coordinates: s from left to right, t from the top (0) to the bottom (1).
vec2 el_screenUv() {
  vec2 c = gl_FragCoord.xy * u_invViewport;
  return vec2(c.x, 1.0 - c.y);
}
";
