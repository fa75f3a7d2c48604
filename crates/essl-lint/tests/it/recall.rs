//! The recall suite: for each rule, a minimal shader per kind of value that reaches its hazard
//! — a uniform (or two set independently), a varying, a texel, a value the shader computes,
//! rounding, a library function's parameters — each reported at its severity, and guarded twins that are quiet. A kind that
//! cannot reach a rule's hazard, or that the rule leaves to the host by design (an input as
//! such, a per-pixel value that is 0 at isolated points only), has no case; the rules' pages
//! say which.

use essl::diagnostic::Severity;
use essl::source::SourceFile;
use essl::{compile, CompileOptions, Stage};
use essl_lint::{lint, LintOptions};

/// A fragment shader with `functions` before `main` and `body` in `main`; `n` and `l` are unit
/// vectors from varyings, `t` a texel read at a varying's coordinates; `v_normal` and `v_color`
/// are named for what they hold.
fn shader_with(precision: &str, functions: &str, body: &str) -> String {
    format!(
        "#version 300 es\nprecision {precision} float;\nprecision highp int;\n\
         uniform bool u_on; uniform bool u_two;\n\
         uniform float u_a; uniform float u_b; uniform float u_k; uniform vec3 u_up; uniform vec3 u_dir;\n\
         uniform sampler2D u_tex; uniform float u_gamma; uniform int u_sampleCount; uniform vec2 u_resolution;\n\
         in vec3 v_n; in vec3 v_h; in vec3 v_pos; in float v_x; in vec2 v_uv;\n\
         in vec3 v_normal; in vec4 v_color;\n\
         out vec4 o;\n{functions}\nvoid main() {{\n  float r = 0.0;\n  vec3 n = normalize(v_n);\n  \
         vec3 l = normalize(v_h);\n  vec4 t = texture(u_tex, v_uv);\n{body}\n  o = vec4(r);\n}}\n"
    )
}

/// The findings of `rule` in `body`, notes included: (severity, source line).
fn found(precision: &str, rule: &str, body: &str) -> Vec<(Severity, String)> {
    found_with(precision, rule, "", body)
}

/// [`found`] with `functions` declared before `main`.
fn found_with(precision: &str, rule: &str, functions: &str, body: &str) -> Vec<(Severity, String)> {
    let text = shader_with(precision, functions, body);
    let s = super::compiled("t.frag", &text);
    lint(&s, &LintOptions::default().notes(true))
        .into_iter()
        .filter(|d| d.code == rule)
        .map(|d| {
            let line = s.file.line_col(d.span.start).line as usize;
            (
                d.severity,
                text.lines().nth(line - 1).unwrap_or("").trim().to_string(),
            )
        })
        .collect()
}

const W: Severity = Severity::Warning;
const N: Severity = Severity::Note;

/// One hazard: the rule, the kind of value that reaches it, the body, the severity.
type Hazard = (&'static str, &'static str, &'static str, Severity);

const HAZARDS: &[Hazard] = &[
    // A divisor that constants make 0: a count of 1 layer.
    (
        "division-by-difference",
        "constant",
        "  float m = float(1);\n  r = v_x / (m - 1.0);",
        W,
    ),
    ("pow-negative-base", "computed", "  r = pow(dot(n, l), u_k);", W),
    ("pow-negative-base", "varying", "  r = pow(v_x - 0.5, 2.2);", W),
    ("pow-negative-base", "texture", "  r = pow(t.r - 0.5, 2.2);", W),
    ("pow-negative-base", "uniform", "  r = pow(u_a - 1.0, 2.2);", N),
    ("pow-negative-base", "rounding", "  r = pow(1.0 - length(n), 2.2);", W),
    ("pow-zero-base", "uniform", "  r = pow(max(dot(n, l), 0.0), u_k - 1.0);", N),
    // A uniform exponent as such is 0 when the uniform is, with a base 0 over a region.
    ("pow-zero-base", "uniform", "  r = pow(max(dot(n, l), 0.0), u_k);", N),
    ("pow-zero-base", "uniform", "  r = pow(clamp(t.r - 0.5, 0.0, 1.0), u_k);", N),
    ("pow-zero-base", "texture", "  r = pow(t.r, u_k);", N),
    // A negated uniform is not positive for positive uniforms: 0 at isolated pixels is enough.
    ("pow-zero-base", "uniform", "  r = pow(abs(v_x - 0.5), -u_k);", N),
    ("acos-domain", "computed", "  r = acos(v_x * 2.0);", W),
    ("acos-domain", "texture", "  r = acos(t.r * 2.0 - 0.5);", W),
    ("acos-domain", "uniform", "  r = acos(u_a * 2.0);", N),
    ("acos-domain", "rounding", "  r = acos(dot(n, l));", W),
    ("acos-domain", "rounding", "  r = acos(v_pos.z / length(v_pos));", W),
    ("asin-domain", "computed", "  r = asin(v_x * 2.0);", W),
    ("asin-domain", "texture", "  r = asin(t.r * 2.0 - 0.5);", W),
    ("asin-domain", "uniform", "  r = asin(u_a * 2.0);", N),
    ("asin-domain", "rounding", "  r = asin(dot(n, l));", W),
    ("smoothstep-edges", "uniform", "  r = smoothstep(u_a, u_b, v_x);", W),
    ("smoothstep-edges", "uniform", "  r = smoothstep(0.0, u_b, v_x);", N),
    ("smoothstep-edges", "varying", "  r = smoothstep(v_x, v_pos.x, 0.5);", W),
    ("smoothstep-edges", "texture", "  r = smoothstep(t.r, t.g, v_x);", W),
    (
        "smoothstep-edges",
        "computed",
        "  float d = dot(n, l);\n  r = smoothstep(clamp(d - 0.3, 0.0, 1.0), clamp(d, 0.0, 1.0), v_x);",
        W,
    ),
    ("smoothstep-edges", "rounding", "  r = smoothstep(u_a, u_a + 1e-9, v_x);", W),
    // The antialiasing idiom: edges equal wherever `v_x` is the same across the pixel quad.
    (
        "smoothstep-edges",
        "derivative",
        "  float w = fwidth(v_x);\n  r = smoothstep(max(0.0, 0.5 - w), 0.5 + w, v_x);",
        N,
    ),
    ("smoothstep-reversed-constant", "constant", "  r = smoothstep(1.0, 0.0, v_x);", N),
    ("clamp-bounds", "constant", "  r = clamp(v_x, 1.0, 0.0);", W),
    ("clamp-bounds", "constant", "  r = clamp(t.rg, vec2(0.0, 1.0), vec2(1.0, 0.5)).y;", W),
    // The value and the bounds in the wrong order: reversed wherever the last is below 1.
    ("clamp-bounds", "varying", "  r = clamp(0.0, 1.0, v_x);", W),
    ("clamp-bounds", "texture", "  r = clamp(0.0, 1.0, t.r);", W),
    ("clamp-bounds", "computed", "  r = clamp(0.0, 1.0, float(gl_FrontFacing));", W),
    ("clamp-bounds", "uniform", "  r = clamp(0.3, 1.0, 1.05 - u_a * 0.5);", W),
    ("division-by-difference", "uniform", "  r = v_x / (u_a - u_b);", W),
    ("division-by-difference", "uniform", "  r = v_x / (u_a - 1.0);", N),
    // The squared length of a cross product of two directions a user sets: 0 when parallel.
    (
        "division-by-difference",
        "uniform",
        "  vec3 c = cross(u_up, u_dir);\n  r = dot(v_pos, c) / dot(c, c);",
        W,
    ),
    (
        "division-by-difference",
        "texture",
        "  float k = min(1.0 - t.r, min(1.0 - t.g, 1.0 - t.b));\n  r = (1.0 - t.r - k) / (1.0 - k);",
        W,
    ),
    ("division-by-difference", "texture", "  r = t.r / (1.0 - t.a);", W),
    ("division-by-difference", "texture", "  r = t.r / t.a;", W),
    // A disjunction that leaves the divisor free on one side is no guard.
    (
        "division-by-difference",
        "texture",
        "  float b = t.r;\n  if (v_x > 0.5 || (b > -1e-6 && v_x < 0.2)) { o = vec4(0.0); return; }\n  r = 1.0 / b;",
        W,
    ),
    // Sums, products and `dot`s of texels: 0 wherever the texture is black (a luminance, the
    // X + Y + Z of a chromaticity).
    (
        "division-by-difference",
        "texture",
        "  float lum = dot(t.rgb, vec3(0.2126, 0.7152, 0.0722));\n  r = lum / (1.0 + lum) / lum;",
        W,
    ),
    (
        "division-by-difference",
        "texture",
        "  vec3 xyz = mat3(0.41, 0.21, 0.02, 0.36, 0.72, 0.12, 0.18, 0.07, 0.95) * t.rgb;\n  r = xyz.r / (xyz.r + xyz.g + xyz.b);",
        W,
    ),
    // The largest of texels: 0 where all are black (FSR's neighbourhood `max`).
    (
        "division-by-difference",
        "texture",
        "  float mx = max(max(t.r, t.g), t.b);\n  r = 1.0 / (4.0 * mx);",
        W,
    ),
    // What is left of a varying outside a box: the zero vector for every pixel inside it.
    (
        "normalize-zero",
        "varying",
        "  vec3 p = vec3(v_uv, v_x) * 2.0;\n  r = normalize(p - clamp(p, -1.0, 1.0)).x;",
        W,
    ),
    (
        "division-by-difference",
        "varying",
        "  vec2 xy = 2.0 * v_uv - vec2(0.5);\n  vec2 delta = 2.0 * (xy - clamp(xy, 0.0, 1.0));\n  r = delta.x / length(delta);",
        W,
    ),
    // One minus a luminance whose weights sum to 1 as `float`s to within rounding: 0 (or
    // 6e-8) where the texture is white, with an epsilon below a `float`'s resolution at 1.
    (
        "division-by-difference",
        "rounding",
        "  float y = dot(t.rgb, vec3(0.299, 0.587, 0.114));\n  r = (1.0 - t.r) / (1e-10 + 1.0 - y);",
        W,
    ),
    // A difference written as a sum with a negative constant: 0 where the texel is white.
    (
        "division-by-difference",
        "texture",
        "  vec2 pk = vec2(1.0, -4.0);\n  r = 1.0 / (4.0 * t.r + pk.y);",
        W,
    ),
    // A uniform as such whose name says a user may set it to 0: a gamma, a count.
    ("division-by-difference", "uniform", "  r = pow(t.r, 1.0 / u_gamma);", N),
    ("division-by-difference", "uniform", "  r = v_x / float(u_sampleCount);", N),
    // A multiple of one: 0 for the whole draw when the setting is.
    (
        "division-by-difference",
        "uniform",
        "  float w = u_gamma * sqrt(abs(v_x));\n  r = v_x / w;",
        N,
    ),
    // A blend of settings: 0 for the whole draw once each setting in it is, whatever the
    // weights (Babylon's two blob fades mixed by a vertex colour, a wavelength pair per row).
    (
        "division-by-difference",
        "uniform",
        "  float w = mix(u_gamma, float(u_sampleCount), v_x);\n  r = v_x / w;",
        N,
    ),
    (
        "division-by-difference",
        "uniform",
        "  float w = (float(u_sampleCount) - u_gamma) * v_x + u_gamma;\n  r = 1.0 / w;",
        N,
    ),
    // A visibility term's denominator, 0 wherever the surface faces away from the light.
    (
        "division-by-difference",
        "computed",
        "  float nl = max(dot(n, l), 0.0);\n  float nv = max(dot(n, normalize(-v_pos)), 0.0);\n  r = 1.0 / (4.0 * (nl + nv - nl * nv));",
        W,
    ),
    ("normalize-zero", "uniform", "  r = normalize(cross(u_up, u_dir)).x;", W),
    ("normalize-zero", "varying", "  r = normalize(cross(v_n, vec3(0.0, 1.0, 0.0))).x;", W),
    (
        "normalize-zero",
        "texture",
        "  vec3 tn = t.xyz * 2.0 - 1.0;\n  r = normalize(cross(tn, vec3(0.0, 1.0, 0.0))).x;",
        W,
    ),
    ("normalize-zero", "computed", "  r = normalize(u_dir - u_up).x;", W),
    ("domain-sqrt", "computed", "  r = sqrt(dot(n, l));", W),
    ("domain-sqrt", "varying", "  r = sqrt(v_x - 0.5);", W),
    ("domain-sqrt", "texture", "  r = sqrt(t.r - 0.5);", W),
    ("domain-sqrt", "uniform", "  r = sqrt(u_a - 1.0);", N),
    ("domain-sqrt", "rounding", "  float c = dot(n, l);\n  r = sqrt(1.0 - c * c);", W),
    ("domain-inversesqrt", "computed", "  r = inversesqrt(max(dot(n, l), 0.0));", W),
    ("domain-inversesqrt", "texture", "  r = inversesqrt(t.r);", W),
    ("domain-inversesqrt", "uniform", "  r = inversesqrt(u_a - 1.0);", N),
    ("domain-inversesqrt", "rounding", "  r = inversesqrt(1.0 - length(n));", W),
    ("domain-log", "computed", "  r = log(dot(n, l));", W),
    ("domain-log", "texture", "  r = log(t.r);", W),
    ("domain-log", "uniform", "  r = log(u_a - 1.0);", N),
    ("domain-log", "uniform", "  r = log2(abs(u_a));", N),
    ("domain-log", "uniform", "  r = -2.0 * log2(1.16 * u_a);", N),
    ("domain-log", "rounding", "  r = log2(1.0 - length(n));", W),
    (
        "domain-atan2",
        "texture",
        "  vec3 nm = texture(u_tex, v_uv).xyz * 2.0 - 1.0;\n  r = atan(nm.y, nm.x);",
        W,
    ),
    (
        "domain-atan2",
        "computed",
        "  vec3 nm = normalize(texture(u_tex, v_uv).xyz * 2.0 - 1.0);\n  r = atan(nm.z, nm.x);",
        W,
    ),
    ("domain-atan2", "uniform", "  r = atan(u_a - 1.0, u_b - 1.0);", W),
    (
        "domain-atan2",
        "named",
        "  vec3 nn = normalize(v_normal);\n  r = atan(nn.y, nn.x);",
        W,
    ),
    ("acos-domain", "named", "  r = acos(v_normal.z);", W),
    (
        "normalize-zero",
        "texture",
        "  float a = texture(u_tex, v_uv + vec2(0.01, 0.0)).r;\n  float b = texture(u_tex, v_uv - vec2(0.01, 0.0)).r;\n  \
         vec2 g = vec2(0.0);\n  g.x = a - b;\n  g.y = 2.0 * b - 2.0 * a;\n  r = normalize(g).x;",
        W,
    ),
    (
        "normalize-zero",
        "texture",
        "  float dx = texture(u_tex, v_uv + vec2(0.01, 0.0)).r - texture(u_tex, v_uv - vec2(0.01, 0.0)).r;\n  \
         float dy = texture(u_tex, v_uv + vec2(0.0, 0.01)).r - texture(u_tex, v_uv - vec2(0.0, 0.01)).r;\n  \
         r = normalize(vec2(dx, dy)).x;",
        W,
    ),
    (
        "division-by-difference",
        "named",
        "  float k = min(1.0 - v_color.r, 1.0 - v_color.g);\n  r = v_color.b / (1.0 - k);",
        W,
    ),
    ("domain-integer-division", "varying", "  int k = int(v_x * 4.0);\n  r = float(12 / k);", W),
    ("domain-integer-division", "texture", "  int k = int(t.r * 4.0);\n  r = float(12 % k);", W),
    ("domain-integer-division", "uniform", "  r = float(12 / int(u_a));", N),
    (
        "domain-integer-division",
        "computed",
        "  int c = int(floor(v_x * 8.0 - 4.0));\n  r = float(c % 2);",
        W,
    ),
    (
        "domain-integer-division",
        "computed",
        "  int k = int(length(n)) - 1;\n  r = float(12 / k);",
        W,
    ),
    (
        "texel-fetch-range",
        "computed",
        "  ivec2 p = ivec2(gl_FragCoord.xy);\n  r = texelFetch(u_tex, p - ivec2(1, 0), 0).r;",
        W,
    ),
    (
        "texel-fetch-range",
        "computed",
        "  ivec2 p = ivec2(gl_FragCoord.xy);\n  r = texelFetch(u_tex, p + ivec2(1, 0), 0).r;",
        W,
    ),
    (
        "texel-fetch-range",
        "texture",
        "  ivec2 p = ivec2(t.xy * 255.0) - 1;\n  r = texelFetch(u_tex, p, 0).r;",
        W,
    ),
    ("texel-fetch-range", "uniform", "  r = texelFetch(u_tex, ivec2(0), int(u_a) - 1).r;", N),
    (
        "texel-fetch-range",
        "uniform",
        "  ivec2 c = ivec2(v_uv * vec2(textureSize(u_tex, 0)));\n  r = texelFetch(u_tex, c, int(u_a)).r;",
        W,
    ),
    (
        "uninitialised-read",
        "varying",
        "  float c;\n  if (v_x > 0.5) { c = 1.0; }\n  r = c;",
        W,
    ),
    (
        "uninitialised-read",
        "uniform",
        "  float c;\n  if (u_a > 0.5) { c = 1.0; }\n  r = c;",
        W,
    ),
    (
        "uninitialised-read",
        "uniform",
        "  float c;\n  for (int i = 0; i < int(u_a); i++) { c = float(i); }\n  r = c;",
        W,
    ),
    // A loop whose counter stops at 2 writes `c.rgb` through `c[i]`, not `c.a` (three.js's
    // dispersion loop, `transmittedLight[ i ]` then `transmittedLight.a`).
    (
        "uninitialised-read",
        "computed",
        "  vec4 c;\n  for (int i = 0; i < 3; i++) { c[i] = t[i]; }\n  r = c.a;",
        W,
    ),
    (
        "uninitialised-read",
        "computed",
        "  vec4 c;\n  for (int i = 3; i > 0; i--) { c[i] = t[i]; }\n  r = c.x;",
        W,
    ),
    // The write's `if` on a uniform runs only where the outer `if` on a varying does.
    (
        "uninitialised-read",
        "varying",
        "  float c;\n  if (v_x > 0.5) { if (u_on) { c = 1.0; } }\n  r = 0.0;\n  if (u_on) { r = c; }",
        W,
    ),
    (
        "non-uniform-derivative",
        "varying",
        "  if (v_x > 0.5) { r = texture(u_tex, v_uv).r; }",
        W,
    ),
    ("non-uniform-derivative", "texture", "  if (t.a > 0.5) { r = dFdx(v_x); }", W),
    ("non-uniform-derivative", "computed", "  if (dot(n, l) > 0.0) { r = fwidth(v_x); }", W),
    // A texel as such: the zero vector for a black texel (a G-buffer's background).
    ("normalize-zero", "texture", "  r = normalize(t.rgb).x;", W),
    // Through a matrix: the zero vector wherever the texel is.
    ("normalize-zero", "texture", "  r = normalize(mat3(u_a) * t.rgb).x;", W),
    // A point minus the point it was offset from is the offset, a texel through a matrix.
    (
        "division-by-difference",
        "texture",
        "  vec3 sw = v_pos;\n  vec3 se = mat3(u_a) * t.rgb + sw;\n  r = v_x / length(se - sw);",
        W,
    ),
    // A derivative's width as a divisor: 0 wherever the value is the same across the quad (a
    // grid coordinate along a face's normal, whose distance to a line is 0 there too: NaN),
    // also through a local a guard on a uniform floors only sometimes; over a texel's flat
    // stretches (±∞, which a clamp makes the right coverage), a note.
    (
        "division-by-difference",
        "derivative",
        "  r = abs(fract(v_x) - 0.5) / fwidth(v_x);",
        W,
    ),
    (
        "division-by-difference",
        "derivative",
        "  float w = length(vec2(dFdx(v_x), dFdy(v_x)));\n  if (u_a > 0.0) { w = max(w, u_a); }\n  r = (v_x - floor(v_x)) / (w * u_b);",
        W,
    ),
    (
        "division-by-difference",
        "texture",
        "  float d = t.r - 0.5;\n  r = clamp(d / fwidth(d) + 0.5, 0.0, 1.0);",
        N,
    ),
    // After a `discard` some pixels take: undefined by the specification, kept working by
    // GPUs that run discarded pixels on as helpers.
    (
        "non-uniform-derivative",
        "texture",
        "  if (t.a < 0.5) discard;\n  r = texture(u_tex, v_uv * 2.0).r;",
        N,
    ),
    // Near misses of the algebraic shapes the guarded twins below rely on.
    // `c - k μ` with `c < |k|`: negative where μ is near 1.
    ("pow-negative-base", "computed", "  r = pow(1.5776 - 2.0 * dot(n, l), 1.5);", W),
    // A completed square with too little left over: `0.5 + g² - 2 g μ` is −0.5 at g = μ = 1.
    (
        "pow-negative-base",
        "computed",
        "  float g = v_x;\n  float gg = g * g;\n  r = pow(0.5 + gg - 2.0 * g * dot(n, l), 1.5);",
        W,
    ),
    // `(x - y x) x` with `y` up to 2: `x² (1 - y)` is negative for `y > 1`.
    (
        "domain-sqrt",
        "computed",
        "  float y = 2.0 * t.r;\n  r = sqrt((v_x - y * v_x) * v_x);",
        W,
    ),
    // A Fibonacci-sphere height from a hash of corners offset by a seed that may be
    // fractional: the hash reaches 288.99 and `1 - sz²` −0.0069.
    (
        "domain-sqrt",
        "uniform",
        "  vec3 i0 = floor(v_pos * 10.0) + u_a;\n  vec3 x = ((i0 * 34.0) + 1.0) * i0;\n  vec3 h = x - floor(x * (1.0 / 289.0)) * 289.0;\n  float sz = h.x * -0.006920415 + 0.996539792;\n  r = sqrt(1.0 - sz * sz);",
        W,
    ),
    // Written on the right of `||`, which does not run where the left is true.
    (
        "uninitialised-read",
        "varying",
        "  float c;\n  bool ok = v_x > 0.5 || (c = 1.0) > 0.0;\n  if (ok) { r = c; }",
        W,
    ),
    // `pow(2, k)` of a `k` that can be negative truncates to 0.
    (
        "domain-integer-division",
        "computed",
        "  int d = int(pow(2.0, float(int(v_x * 9.0) % 4 - 3)));\n  r = float(int(v_x * 1000.0) / d);",
        W,
    ),
    // A geometric series whose weights do not shrink (`w *= 1.0`): the sum passes 1.
    (
        "domain-sqrt",
        "texture",
        "  float s = 0.0;\n  float w = 0.5;\n  for (int i = 0; i < 8; i++) { s += clamp(t.r, 0.0, 1.0) * w; w *= 1.0; }\n  r = sqrt(1.0 - s);",
        W,
    ),
    // The same with a first weight of 0.6: the sum reaches 1.2.
    (
        "domain-sqrt",
        "texture",
        "  float s = 0.0;\n  float w = 0.6;\n  for (int i = 0; i < 8; i++) { s += clamp(t.r, 0.0, 1.0) * w; w *= 0.5; }\n  r = sqrt(1.0 - s);",
        W,
    ),
    // A `continue` that adds a term and skips the weight's update.
    (
        "domain-sqrt",
        "texture",
        "  float s = 0.0;\n  float w = 0.5;\n  for (int i = 0; i < 8; i++) { s += clamp(t.r, 0.0, 1.0) * w; if (v_x > 0.5) continue; w *= 0.5; }\n  r = sqrt(1.0 - s);",
        W,
    ),
    // The weight shrinks only under an `if`.
    (
        "domain-sqrt",
        "texture",
        "  float s = 0.0;\n  float w = 0.5;\n  for (int i = 0; i < 8; i++) { s += clamp(t.r, 0.0, 1.0) * w; if (v_x > 0.5) { w *= 0.5; } }\n  r = sqrt(1.0 - s);",
        W,
    ),
    // A weight that grows (`w *= 2.0`): no bound.
    (
        "domain-sqrt",
        "texture",
        "  float s = 0.0;\n  float w = 0.25;\n  for (int i = 0; i < 8; i++) { s += clamp(t.r, 0.0, 1.0) * w; w *= 2.0; }\n  r = sqrt(1.0 - s);",
        W,
    ),
];

/// The guarded twins: (rule, body) with no finding of the rule, notes included.
const GUARDED: &[(&str, &str)] = &[
    // A derivative's width kept from 0, and the length of a position's derivative (0 only where
    // the whole position is the same across the quad, which a surface's never is).
    (
        "division-by-difference",
        "  r = abs(fract(v_x) - 0.5) / max(fwidth(v_x), 1e-4);",
    ),
    (
        "division-by-difference",
        "  r = 1.0 / max(length(dFdx(v_pos)), length(dFdy(v_pos)));",
    ),
    // The branch that would divide by the constant 0 is never taken.
    (
        "division-by-difference",
        "  const int k = 1;\n  if (k > 1) {\n    r = v_x / float(k - 1);\n  }",
    ),
    (
        "division-by-difference",
        "  vec3 c = cross(u_up, u_dir);\n  float c2 = dot(c, c);\n  r = c2 > 1e-8 ? dot(v_pos, c) / c2 : 0.0;",
    ),
    // 0 only at a middle value of the texel, not over a region.
    ("division-by-difference", "  r = 1.0 / (4.0 * t.r + -2.0);"),
    // A `max` with a constant floor is a guard.
    (
        "division-by-difference",
        "  float mx = max(max(t.r, t.g), 1e-4);\n  r = 1.0 / (4.0 * mx);",
    ),
    // An early return on either of two conditions, one of them a band around 0; and one on
    // the divisor's own value, divided through a copy.
    (
        "division-by-difference",
        "  float b = t.r;\n  if (v_x > 0.5 || (b > -1e-6 && b < 1e-6)) { o = vec4(0.0); return; }\n  r = 1.0 / b;",
    ),
    (
        "division-by-difference",
        "  float b = abs(t.r);\n  if (v_x > 0.5 || b == 0.0) { o = vec4(0.0); return; }\n  float d = b;\n  r = 1.0 / d;",
    ),
    // A direction not named a normal, and one that varies per pixel through a view ray: the
    // axis at isolated pixels.
    ("domain-atan2", "  vec3 nn = normalize(v_h);\n  r = atan(nn.y, nn.x);"),
    (
        "domain-atan2",
        "  vec3 nn = reflect(normalize(v_pos), normalize(v_normal));\n  r = atan(nn.z, nn.x);",
    ),
    ("acos-domain", "  r = acos(clamp(v_normal.z, -1.0, 1.0));"),
    ("domain-log", "  r = -2.0 * log2(max(1.16 * u_a, 1e-6));"),
    // An alpha tested first, or kept above 0.
    ("division-by-difference", "  r = t.a > 0.0 ? t.r / t.a : 0.0;"),
    ("division-by-difference", "  r = t.r / max(t.a, 1e-4);"),
    (
        "division-by-difference",
        "  float lum = dot(t.rgb, vec3(0.2126, 0.7152, 0.0722));\n  r = lum / max(lum, 1e-4) + t.r / (t.r + t.g + 1e-3);",
    ),
    (
        "division-by-difference",
        "  float s = t.r + t.g + t.b;\n  r = s > 0.0 ? t.r / s : 0.0;",
    ),
    // A blend of settings kept above 0, and one with a uniform that names no setting.
    (
        "division-by-difference",
        "  float w = mix(u_gamma, float(u_sampleCount), v_x);\n  r = v_x / max(w, 1e-4) + v_x / mix(u_gamma, u_a, v_x);",
    ),
    // A size the host takes from the canvas, and a guarded setting.
    (
        "division-by-difference",
        "  r = gl_FragCoord.x / u_resolution.x + pow(t.r, 1.0 / max(u_gamma, 1e-4));",
    ),
    (
        "division-by-difference",
        "  float nl = max(dot(n, l), 0.0);\n  float nv = max(dot(n, normalize(-v_pos)), 0.0);\n  r = 1.0 / max(4.0 * (nl + nv - nl * nv), 1e-4);",
    ),
    // A normal from a height map has a constant component; a weighted sum whose weights do not
    // cancel is no gradient.
    (
        "normalize-zero",
        "  float a = texture(u_tex, v_uv + vec2(0.01, 0.0)).r;\n  float b = texture(u_tex, v_uv - vec2(0.01, 0.0)).r;\n  \
         vec3 g = vec3(0.0, 0.0, 1.0);\n  g.x = a - b;\n  g.y = b - a;\n  r = normalize(g).x;",
    ),
    (
        "normalize-zero",
        "  float dx = texture(u_tex, v_uv + vec2(0.01, 0.0)).r - texture(u_tex, v_uv - vec2(0.01, 0.0)).r;\n  \
         float dy = texture(u_tex, v_uv + vec2(0.0, 0.01)).r - texture(u_tex, v_uv - vec2(0.0, 0.01)).r;\n  \
         r = normalize(vec3(dx, dy, 1.0)).x;",
    ),
    (
        "normalize-zero",
        "  float a = texture(u_tex, v_uv + vec2(0.01, 0.0)).r;\n  float b = texture(u_tex, v_uv - vec2(0.01, 0.0)).r;\n  \
         r = normalize(vec2(a - b, a + b + 0.5)).x;",
    ),
    (
        "domain-integer-division",
        "  int c = int(floor(v_x * 8.0 - 4.0));\n  r = float(abs(c) % 2);",
    ),
    (
        "domain-integer-division",
        "  int c = int(floor(v_x * 8.0 - 4.0));\n  if (c >= 0) { r = float(c % 2); }",
    ),
    // An input as such is the caller's to keep non-negative.
    ("domain-integer-division", "  r = float(int(v_x) % 2);"),
    (
        "division-by-difference",
        "  float k = min(1.0 - v_color.r, 1.0 - v_color.g);\n  r = v_color.b / max(1.0 - k, 1e-4);",
    ),
    ("pow-negative-base", "  r = pow(max(dot(n, l), 0.0), u_k);"),
    ("pow-negative-base", "  r = pow(clamp(t.r - 0.5, 0.0, 1.0), 2.2);"),
    ("pow-zero-base", "  r = pow(max(dot(n, l), 1e-4), u_k - 1.0);"),
    ("pow-zero-base", "  r = pow(max(dot(n, l), 0.0), max(u_k, 1e-4));"),
    ("pow-zero-base", "  if (u_k > 0.0) { r = pow(max(dot(n, l), 0.0), u_k); }"),
    ("pow-zero-base", "  r = pow(max(t.r, 1e-4), u_k);"),
    // A uniform exponent with a base 0 at isolated pixels only (a varying's crossing).
    ("pow-zero-base", "  r = pow(abs(v_x - 0.5), u_k);"),
    ("acos-domain", "  r = acos(clamp(dot(n, l), -1.0, 1.0));"),
    ("acos-domain", "  r = acos(clamp(v_pos.z / length(v_pos), -1.0, 1.0));"),
    ("asin-domain", "  r = asin(clamp(v_x * 2.0, -1.0, 1.0));"),
    ("smoothstep-edges", "  if (u_a < u_b) { r = smoothstep(u_a, u_b, v_x); }"),
    (
        "smoothstep-edges",
        "  float d = dot(n, l);\n  float e0 = clamp(d - 0.3, 0.0, 1.0);\n  r = smoothstep(e0, max(clamp(d, 0.0, 1.0), e0 + 1e-3), v_x);",
    ),
    // The antialiasing width kept above 0.
    (
        "smoothstep-edges",
        "  float w = max(fwidth(v_x), 1e-4);\n  r = smoothstep(0.5 - w, 0.5 + w, v_x);",
    ),
    // A quotient the guard keeps above 1: `u_a > d >= 0` (a Pixi filter's bulge).
    (
        "smoothstep-edges",
        "  float d = length(v_pos);\n  if (d < u_a) { r = smoothstep(0.0, u_a / d, v_x); }",
    ),
    // A width that only an input as such makes 0 (MapLibre's `gamma * gamma_scale`).
    (
        "smoothstep-edges",
        "  float w = 0.1 / max(u_a, 1.0) * v_x * v_x;\n  r = smoothstep(0.5 - w, 0.5 + w, t.r);",
    ),
    // Clamps of the same value shifted are ordered; the constant keeps them apart.
    (
        "smoothstep-edges",
        "  float d = dot(n, l);\n  r = smoothstep(clamp(d - 0.3, 0.0, 1.0), clamp(d, 0.0, 1.0) + 1e-3, v_x);",
    ),
    ("smoothstep-reversed-constant", "  r = 1.0 - smoothstep(0.0, 1.0, v_x);"),
    ("clamp-bounds", "  r = clamp(v_x, 0.0, 1.0) + clamp(t.r, 0.5, 0.5);"),
    ("clamp-bounds", "  r = clamp(float(gl_FrontFacing), 0.0, 1.0);"),
    // A constant value whose bounds are never reversed: defined, if pointless.
    ("clamp-bounds", "  r = clamp(0.5, 0.0, 1.0 + v_x * v_x);"),
    // A constant between two values: their order is the shader's.
    ("clamp-bounds", "  r = clamp(0.5, v_x, u_a);"),
    ("division-by-difference", "  if (u_a != u_b) { r = v_x / (u_a - u_b); }"),
    (
        "division-by-difference",
        "  float k = min(1.0 - t.r, min(1.0 - t.g, 1.0 - t.b));\n  r = (1.0 - t.r - k) / max(1.0 - k, 1e-4);",
    ),
    // A value outside a box tested first, and a box whose size a uniform sets (empty at 0).
    (
        "normalize-zero",
        "  vec3 p = vec3(v_uv, v_x) * 2.0;\n  vec3 q = p - clamp(p, -1.0, 1.0);\n  r = dot(q, q) > 1e-12 ? normalize(q).x : 0.0;",
    ),
    (
        "normalize-zero",
        "  vec3 p = vec3(v_uv, v_x) * 2.0;\n  r = normalize(p - clamp(p, -u_a, u_a)).x;",
    ),
    // An epsilon added after the difference keeps it from 0; one above the rounding, before.
    (
        "division-by-difference",
        "  float y = dot(t.rgb, vec3(0.299, 0.587, 0.114));\n  r = (1.0 - t.r) / (1.0 - y + 1e-10);",
    ),
    (
        "division-by-difference",
        "  float y = dot(t.rgb, vec3(0.299, 0.587, 0.114));\n  r = (1.0 - t.r) / (1e-4 + 1.0 - y);",
    ),
    // Differences of texels 0 inside their range only: at isolated values, not at black or white.
    ("division-by-difference", "  r = v_x / (t.r - t.g);"),
    ("division-by-difference", "  r = v_x / (t.r * 2.0 - 1.0);"),
    (
        "normalize-zero",
        "  vec3 c = cross(u_up, u_dir);\n  if (length(c) > 0.0) { r = normalize(c).x; }",
    ),
    (
        "normalize-zero",
        "  vec3 tn = t.xyz * 2.0 - 1.0;\n  vec3 up = abs(tn.y) < 0.999 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);\n  r = normalize(cross(tn, up)).x;",
    ),
    ("domain-sqrt", "  r = sqrt(max(dot(n, l), 0.0));"),
    (
        "domain-inversesqrt",
        "  vec3 d = v_pos - u_dir;\n  r = inversesqrt(max(dot(d, d), 1e-8));",
    ),
    ("domain-log", "  r = log(max(dot(n, l), 1e-6));"),
    ("domain-log", "  r = log2(max(abs(u_a), 1e-6));"),
    (
        "domain-atan2",
        "  vec3 nm = texture(u_tex, v_uv).xyz * 2.0 - 1.0;\n  r = (abs(nm.x) + abs(nm.y) > 1e-6) ? atan(nm.y, nm.x) : 0.0;",
    ),
    (
        "domain-atan2",
        "  vec3 nm = texture(u_tex, v_uv).xyz * 2.0 - 1.0;\n  if (abs(nm.x) > 0.0) { r = atan(nm.y, nm.x); }",
    ),
    (
        "domain-atan2",
        "  vec2 d = normalize(texture(u_tex, v_uv).xy * 2.0 - 1.0);\n  r = atan(d.y, d.x);",
    ),
    ("domain-atan2", "  if (u_a != 1.0) { r = atan(u_a - 1.0, u_b - 1.0); }"),
    // A normal-map texel turned by an interpolated frame varies per pixel.
    (
        "domain-atan2",
        "  vec3 nm = normalize(mat3(v_n, v_h, v_pos) * (texture(u_tex, v_uv).xyz * 2.0 - 1.0));\n  r = atan(nm.z, nm.x);",
    ),
    (
        "domain-integer-division",
        "  int k = max(int(v_x * 4.0), 1);\n  r = float(12 / k);",
    ),
    (
        "domain-integer-division",
        "  int k = int(t.r * 4.0);\n  r = float(12 % max(k, 1));",
    ),
    // Coordinates brought to the level read, or scaled by its own size.
    (
        "texel-fetch-range",
        "  int lod = int(u_a);\n  ivec2 c = ivec2(v_uv * vec2(textureSize(u_tex, 0))) >> lod;\n  \
         r = texelFetch(u_tex, c, lod).r;",
    ),
    (
        "texel-fetch-range",
        "  int lod = int(u_a);\n  ivec2 c = ivec2(v_uv * vec2(textureSize(u_tex, lod)));\n  \
         r = texelFetch(u_tex, c, lod).r;",
    ),
    (
        "texel-fetch-range",
        "  ivec2 p = ivec2(gl_FragCoord.xy);\n  r = texelFetch(u_tex, clamp(p - ivec2(1, 0), ivec2(0), textureSize(u_tex, 0) - 1), 0).r;",
    ),
    (
        "texel-fetch-range",
        "  ivec2 p = max(ivec2(t.xy * 255.0) - 1, ivec2(0));\n  r = texelFetch(u_tex, p, 0).r;",
    ),
    (
        "texel-fetch-range",
        "  r = texelFetch(u_tex, ivec2(0), max(int(u_a) - 1, 0)).r;",
    ),
    // A mip reduction: texel `2p + 1` of a level twice the size of the one `p` indexes.
    (
        "texel-fetch-range",
        "  ivec2 p = ivec2(gl_FragCoord.xy) * 2;\n  r = texelFetch(u_tex, p + ivec2(1, 0), 0).r;",
    ),
    (
        "uninitialised-read",
        "  float c = 0.0;\n  if (v_x > 0.5) { c = 1.0; }\n  r = c;",
    ),
    // Every component through the counter of a loop that reaches each.
    (
        "uninitialised-read",
        "  vec4 c;\n  for (int i = 0; i <= 3; ++i) { c[i] = t[i]; }\n  r = c.a;",
    ),
    (
        "uninitialised-read",
        "  vec3 c;\n  c.z = 1.0;\n  for (int i = 0; i < 2; i += 1) { c[i] = t[i]; }\n  r = c.x + c.z;",
    ),
    // Written under `u_on`, read under `u_on && u_two`: every pixel of the draw takes both.
    (
        "uninitialised-read",
        "  float c;\n  if (u_on) { c = 1.0; }\n  r = 0.0;\n  if (u_on && u_two) { r = c; }",
    ),
    (
        "non-uniform-derivative",
        "  float s = texture(u_tex, v_uv).r;\n  if (v_x > 0.5) { r = s; }",
    ),
    (
        "non-uniform-derivative",
        "  if (v_x > 0.5) { r = textureLod(u_tex, v_uv, 0.0).r; }",
    ),
    ("non-uniform-derivative", "  if (u_a > 0.5) { r = texture(u_tex, v_uv).r; }"),
    // A decoded texel, and a texel whose length is tested first.
    ("normalize-zero", "  r = normalize(t.rgb * 2.0 - 1.0).x;"),
    (
        "normalize-zero",
        "  r = dot(t.rgb, t.rgb) > 1e-12 ? normalize(t.rgb).x : 0.0;",
    ),
    // A `discard` every pixel of the draw takes or none does; a lookup before the `discard`.
    (
        "non-uniform-derivative",
        "  if (u_on) discard;\n  r = texture(u_tex, v_uv * 2.0).r;",
    ),
    (
        "non-uniform-derivative",
        "  vec4 c = texture(u_tex, v_uv * 2.0);\n  if (c.a < 0.5) discard;\n  r = c.r;",
    ),
    // Written on the right of `&&`: wherever the condition, or a local set from it, is true.
    (
        "uninitialised-read",
        "  float c;\n  if (v_x > 0.5 && (c = 1.0) > 0.0) { r = c; }",
    ),
    (
        "uninitialised-read",
        "  float c;\n  bool ok = v_x > 0.5 && (c = 1.0) > 0.0;\n  r = 0.5;\n  if (ok) { r = c; }",
    ),
    // Henyey–Greenstein: `1 + g² - 2 g μ ≥ 1 - μ² ≥ 0` for |μ| ≤ 1, whatever g is (a raw
    // `dot` of unit vectors is 1 + ε at most: the rounding finding stays).
    (
        "pow-negative-base",
        "  float g = v_x;\n  float gg = g * g;\n  float mu = clamp(dot(n, l), -1.0, 1.0);\n  r = (1.0 - gg) / pow(1.0 + gg - 2.0 * g * mu, 1.5);",
    ),
    // The same with a constant g: `1.5776 - 1.52 μ > 0`.
    ("pow-negative-base", "  r = pow(1.5776 - 1.52 * dot(n, l), 1.5);"),
    // The correlated Smith term: `(x - a² x) x + a² = x² (1 - a²) + a²` for a roughness in [0, 1].
    (
        "domain-sqrt",
        "  float a2 = t.g * t.g;\n  float nv = max(dot(n, l), 0.0);\n  r = sqrt((nv - a2 * nv) * nv + a2);",
    ),
    // A product holding a square: `m (x) (x)` with `m > 0`.
    (
        "domain-sqrt",
        "  float m2 = v_x * v_x + 0.25;\n  float q = v_pos.x - 0.5;\n  r = sqrt(m2 * q * q / m2);",
    ),
    // The same hash of whole corners: at most 288, so `sz` stays within ±0.9966.
    (
        "domain-sqrt",
        "  vec3 i0 = floor(v_pos * 10.0);\n  vec3 x = ((i0 * 34.0) + 1.0) * i0;\n  vec3 h = x - floor(x * (1.0 / 289.0)) * 289.0;\n  float sz = h.x * -0.006920415 + 0.996539792;\n  r = sqrt(1.0 - sz * sz);",
    ),
    // `pow(256, k)` of a `k` in [0, 6] is at least 1.
    (
        "domain-integer-division",
        "  int d = int(pow(256.0, float(3 - int(v_x * 9.0) % 4)));\n  r = float(int(v_x * 1000.0) / d);",
    ),
    // Under `b > 0.0` and `b < u_a`, `b / u_a` is in [0, 1).
    (
        "pow-negative-base",
        "  float b = v_x * 3.0 - 1.0;\n  if (b > 0.0) { if (b < u_a) { r = pow(1.0 - b / u_a, 2.0); } }",
    ),
    // Fractal sums: terms in [0, 1] weighted 1/2, 1/4, … stay below 1 (fbm, with the update
    // in the continuing block, and the radical inverse of Hammersley points).
    (
        "domain-sqrt",
        "  float s = 0.0;\n  float w = 0.5;\n  for (int i = 0; i < 8; i++) { s += w * clamp(t.r, 0.0, 1.0); w *= 0.5; }\n  r = sqrt(1.0 - s);",
    ),
    (
        "domain-sqrt",
        "  float s = 0.0;\n  float w = 0.25;\n  for (int i = 0; i < 8; i++, w *= 0.5) { s += clamp(t.r, 0.0, 1.0) * w; if (v_x > 0.5) continue; }\n  r = sqrt(0.5 - s);",
    ),
    (
        "domain-sqrt",
        "  int k = int(v_x * 1000.0);\n  float base = 2.0;\n  float value = 0.0;\n  float inv = 1.0 / base;\n  float w = inv;\n  for (int x = 0; x < 100; x++) {\n    if (k <= 0) break;\n    float b = mod(float(k), base);\n    value += b * w;\n    w *= inv;\n    k = int(float(k) * inv);\n  }\n  r = sqrt(1.0 - value * value);",
    ),
];

/// A parameter's note says where it is 0: at 0 for the parameter itself, at some other value
/// for a sum with a constant (`1.0 - b` is 0 at `b == 1`).
#[test]
fn a_parameter_s_note_says_where_it_is_zero() {
    let message = |functions: &str, body: &str| {
        let text = shader_with("highp", functions, body);
        let s = super::compiled("t.frag", &text);
        lint(&s, &LintOptions::default().notes(true))
            .into_iter()
            .find(|d| d.code == "division-by-difference")
            .map(|d| d.message)
            .unwrap_or_default()
    };
    let itself = message("float inv(float b) { return 1.0 / b; }", "  r = inv(v_x);");
    assert!(
        itself.contains("the parameter `b`, which a caller may pass as 0"),
        "{itself}"
    );
    let offset = message(
        "float hp(float b) { return 1.0 / (1.0 - b); }",
        "  r = hp(v_x);",
    );
    assert!(
        offset.contains("a value of the parameter `b`, 0 for some arguments"),
        "{offset}"
    );
}

/// A division by what a function returns that is a length, scaled (a triangle's area): the
/// vector's zero is the divisor's; with the length kept from 0 inside, quiet.
#[test]
fn a_length_a_function_returns() {
    let area = "float area(vec3 a, vec3 b) { return length(cross(a, b)) * 0.5; }";
    let f = found_with(
        "highp",
        "division-by-difference",
        area,
        "  r = v_x / area(u_up, u_dir);",
    );
    assert!(
        f.iter()
            .any(|(s, l)| *s == W && l == "r = v_x / area(u_up, u_dir);"),
        "{f:?}"
    );
    let kept = "float area(vec3 a, vec3 b) { return max(length(cross(a, b)), 1e-6) * 0.5; }";
    let f = found_with(
        "highp",
        "division-by-difference",
        kept,
        "  r = v_x / area(u_up, u_dir);",
    );
    assert!(f.is_empty(), "{f:?}");
}

#[test]
fn every_hazard_is_reported_at_its_severity() {
    let mut failed = Vec::new();
    for (rule, kind, body, severity) in HAZARDS {
        let f = found("highp", rule, body);
        let last = body.lines().last().unwrap_or("").trim();
        if !f.iter().any(|(s, line)| s == severity && line == last) {
            failed.push(format!(
                "{rule} ({kind}): expected a {} at `{last}`, found {f:?}",
                severity.as_str()
            ));
        }
    }
    assert!(failed.is_empty(), "{}", failed.join("\n"));
}

#[test]
fn guarded_twins_are_quiet() {
    let mut failed = Vec::new();
    for (rule, body) in GUARDED {
        let f = found("highp", rule, body);
        if !f.is_empty() {
            failed.push(format!("{rule}: `{body}` has {f:?}"));
        }
    }
    assert!(failed.is_empty(), "{}", failed.join("\n"));
}

/// A library function's division (or `log`, `pow`, `atan`) of what its callers pass (inputs as
/// such here): a note at the call, naming the parameters; (rule, function, call in `main`, the
/// line of the note or `None` for a twin that is quiet).
const PARAMETERS: &[(&str, &str, &str, Option<&str>)] = &[
    // A size the caller chooses (a grid's cell) is a setting; a texture's size is the host's.
    (
        "division-by-difference",
        "float cells(vec2 resolution, float cellSize) {\n  return resolution.x / cellSize;\n}",
        "  r = cells(v_uv, v_x);",
        Some("return resolution.x / cellSize;"),
    ),
    (
        "division-by-difference",
        "float texels(float x, float texSize) {\n  return x / texSize;\n}",
        "  r = texels(v_uv.x, v_x);",
        None,
    ),
    // A weighted sum: 0 where the caller passes every weight as 0, whatever the colours are.
    (
        "division-by-difference",
        "float mixed(float a, float b, float t1, float t2) {\n  float w = pow(sqrt(a) * t1, 2.0) + pow(sqrt(b) * t2, 2.0);\n  return (a * t1 + b * t2) / w;\n}",
        "  r = mixed(v_pos.x, v_pos.y, v_x, v_uv.x);",
        Some("return (a * t1 + b * t2) / w;"),
    ),
    // 0 at one point of the caller's values (a spiral's centre), not over a region.
    (
        "domain-log",
        "float spiral(vec2 st) {\n  st -= 0.5;\n  float q = dot(st, st);\n  return log(q);\n}",
        "  r = spiral(v_uv);",
        Some("return log(q);"),
    ),
    (
        "division-by-difference",
        "float g(float d, float s) { return exp(-(d * d) / (2.0 * s * s)); }",
        "  r = g(v_x, v_uv.x);",
        Some("float g(float d, float s) { return exp(-(d * d) / (2.0 * s * s)); }"),
    ),
    (
        "division-by-difference",
        "float m(float v, float a, float b) {\n  return (v - a) / (b - a);\n}",
        "  r = m(v_x, v_uv.x, v_uv.y);",
        Some("return (v - a) / (b - a);"),
    ),
    (
        "division-by-difference",
        "float hp(float v, float b) { return max(v - b, 0.0) / (1.0 - b); }",
        "  r = hp(v_x, v_uv.x);",
        Some("float hp(float v, float b) { return max(v - b, 0.0) / (1.0 - b); }"),
    ),
    (
        "division-by-difference",
        "vec2 near(vec2 st, vec2 res) {\n  return st + 0.5 / (res - 1.0);\n}",
        "  r = near(v_uv, v_uv * 0.0 + v_x).x;",
        None,
    ),
    (
        "division-by-difference",
        "vec2 near(vec2 st, vec2 res) {\n  return st + 0.5 / (res - 1.0);\n}",
        "  r = near(v_uv, vec2(v_x)).x;",
        Some("return st + 0.5 / (res - 1.0);"),
    ),
    // Guarded; called with constants; with computed values; a texture's size; the `w` of a
    // homogeneous coordinate; a sum with a constant that ordinary values keep above 0; an
    // index of refraction.
    (
        "division-by-difference",
        "float g(float d, float s) { return exp(-(d * d) / max(2.0 * s * s, 1e-4)); }",
        "  r = g(v_x, v_uv.x);",
        None,
    ),
    (
        "division-by-difference",
        "float m(float v, float a, float b) { return (v - a) / (b - a); }",
        "  r = m(v_x, 0.2, 0.8);",
        None,
    ),
    (
        "division-by-difference",
        "float m(float v, float a, float b) { return (v - a) / (b - a); }",
        "  r = m(v_x, v_uv.x * v_x, v_uv.y + 2.0);",
        None,
    ),
    // One end an input, the other a uniform: a per-pixel difference, 0 on a line of pixels.
    (
        "division-by-difference",
        "float m(float v, float a, float b) { return (v - a) / (b - a); }",
        "  r = m(v_x, v_uv.x, u_a);",
        None,
    ),
    (
        "division-by-difference",
        "vec2 px(vec2 texResolution) { return 1.0 / texResolution; }",
        "  r = px(v_uv).x;",
        None,
    ),
    (
        "division-by-difference",
        "vec3 pr(vec4 p) { return p.xyz / p.w; }",
        "  r = pr(vec4(v_pos, v_x)).x;",
        None,
    ),
    (
        "division-by-difference",
        "float tm(float x) { return x / (x + 0.155); }",
        "  r = tm(v_x);",
        None,
    ),
    (
        "division-by-difference",
        "float eta(float ior) { return 1.0 / ior; }",
        "  r = eta(v_x);",
        None,
    ),
    // 0 where the parameter is: `tan` of it over a constant.
    (
        "division-by-difference",
        "float persp(float fov) {\n  return 1.0 / tan(fov / 2.0);\n}",
        "  r = persp(v_x);",
        Some("return 1.0 / tan(fov / 2.0);"),
    ),
    // `log`, `pow` with an exponent never above 0, and `atan` of what callers pass; guarded,
    // and kept from 0 by a constant.
    (
        "domain-log",
        "float lg(float t) {\n  return log(t);\n}",
        "  r = lg(v_x);",
        Some("return log(t);"),
    ),
    (
        "domain-log",
        "float lg(float t) { return t > 0.0 ? log(t) : 0.0; }",
        "  r = lg(v_x);",
        None,
    ),
    (
        "domain-log",
        "float lg(float t) { return log(t + 1.0); }",
        "  r = lg(v_x);",
        None,
    ),
    (
        "pow-zero-base",
        "float k(float t) {\n  return pow(t, -1.5);\n}",
        "  r = k(v_x);",
        Some("return pow(t, -1.5);"),
    ),
    (
        "pow-zero-base",
        "float k(float t) { return pow(t, 1.5); }",
        "  r = k(v_x);",
        None,
    ),
    (
        "domain-atan2",
        "float ang(vec2 st, vec2 c) {\n  vec2 d = st - c;\n  return atan(d.y, d.x);\n}",
        "  r = ang(v_uv, v_pos.xy);",
        Some("return atan(d.y, d.x);"),
    ),
    (
        "domain-atan2",
        "float ang(vec2 st, vec2 c) {\n  vec2 d = st - c;\n  return abs(d.x) + abs(d.y) > 1e-6 ? atan(d.y, d.x) : 0.0;\n}",
        "  r = ang(v_uv, v_pos.xy);",
        None,
    ),
    // Scalars as such, and a parameter written from itself.
    (
        "domain-atan2",
        "float a2(float y, float x) {\n  return atan(y, x);\n}",
        "  r = a2(v_x, v_uv.x);",
        Some("return atan(y, x);"),
    ),
    (
        "domain-atan2",
        "float poly(vec2 st) {\n  st = st * 2.0 - 1.0;\n  return atan(st.x, st.y);\n}",
        "  r = poly(v_uv);",
        Some("return atan(st.x, st.y);"),
    ),
    (
        "domain-atan2",
        "float a2(vec2 d) { vec2 n = normalize(d); return atan(n.y, n.x); }",
        "  r = a2(v_uv);",
        None,
    ),
    // A difference of two points a caller passes: the zero vector where they are the same.
    (
        "normalize-zero",
        "vec3 look(vec3 eye, vec3 target) { return normalize(target - eye); }",
        "  r = look(v_pos, v_h).x;",
        Some("vec3 look(vec3 eye, vec3 target) { return normalize(target - eye); }"),
    ),
    (
        "normalize-zero",
        "vec3 look(vec3 eye, vec3 target) {\n  vec3 d = target - eye;\n  return dot(d, d) > 1e-12 ? normalize(d) : vec3(0.0, 0.0, 1.0);\n}",
        "  r = look(v_pos, v_h).x;",
        None,
    ),
    // A division by the length of that difference: a normalisation by hand, the same zero
    // vector; the length tested first, quiet.
    (
        "division-by-difference",
        "vec3 dir(vec3 a, vec3 b) {\n  vec3 d = b - a;\n  return d / length(d);\n}",
        "  r = dir(v_pos, v_h).x;",
        Some("return d / length(d);"),
    ),
    (
        "division-by-difference",
        "vec3 dir(vec3 a, vec3 b) {\n  vec3 d = b - a;\n  float l = length(d);\n  return l > 1e-6 ? d / l : vec3(0.0);\n}",
        "  r = dir(v_pos, v_h).x;",
        None,
    ),
    // The same where the locals are written again afterwards: the store that reaches the
    // division is the one that counts (lygia's `arrowSDF`).
    (
        "division-by-difference",
        "float arrow(vec3 v, vec3 a, vec3 b, float h) {\n  vec3 t = b - a;\n  float l = length(t);\n  t /= l;\n  l = max(l, h);\n  return dot(v, t) * l;\n}",
        "  r = arrow(v_h, v_pos, v_h, v_x);",
        Some("t /= l;"),
    ),
    (
        "division-by-difference",
        "float arrow(vec3 v, vec3 a, vec3 b, float h) {\n  vec3 t = b - a;\n  float l = length(t);\n  l = max(l, 1e-4);\n  t /= l;\n  return dot(v, t) * max(l, h);\n}",
        "  r = arrow(v_h, v_pos, v_h, v_x);",
        None,
    ),
    // The antialiasing idiom with the width a parameter every call passes a derivative.
    (
        "smoothstep-edges",
        "float aa(float d, float w) { return smoothstep(0.5 - w, 0.5 + w, d); }",
        "  r = aa(v_x, fwidth(v_x));",
        Some("float aa(float d, float w) { return smoothstep(0.5 - w, 0.5 + w, d); }"),
    ),
    (
        "smoothstep-edges",
        "float aa(float d, float w) { return smoothstep(0.5 - w, 0.5 + w, d); }",
        "  r = aa(v_x, max(fwidth(v_x), 1e-4));",
        None,
    ),
    // A positive power and a quotient are 0 where their base and dividend are.
    (
        "division-by-difference",
        "float inv2(float d) { return 1.0 / pow(d, 2.0); }",
        "  r = inv2(v_x);",
        Some("float inv2(float d) { return 1.0 / pow(d, 2.0); }"),
    ),
    (
        "division-by-difference",
        "float ell(vec3 p, vec3 r) { return 1.0 / length(p / (r * r)); }",
        "  r = ell(v_pos, v_h);",
        Some("float ell(vec3 p, vec3 r) { return 1.0 / length(p / (r * r)); }"),
    ),
    (
        "division-by-difference",
        "float inv2(float d) { return 1.0 / max(pow(d, 2.0), 1e-4); }",
        "  r = inv2(v_x);",
        None,
    ),
    // A scalar a caller passes as such as a `pow` base: an easing's `t`, also on an easing's
    // first half (`t < 0.5` takes every negative `t`); tested against 0 first, or named for a
    // distance, quiet.
    (
        "pow-negative-base",
        "float qi(float t) { return pow(t, 4.0); }",
        "  r = qi(v_x);",
        Some("float qi(float t) { return pow(t, 4.0); }"),
    ),
    (
        "pow-negative-base",
        "float qio(float t) {\n  return t < 0.5\n    ? 8.0 * pow(t, 4.0)\n    : 1.0 - 8.0 * (1.0 - t) * (1.0 - t) * (1.0 - t) * (1.0 - t);\n}",
        "  r = qio(v_x);",
        Some("? 8.0 * pow(t, 4.0)"),
    ),
    (
        "pow-negative-base",
        "float qio(float t) {\n  if (t < 0.0) return 0.0;\n  return t < 0.5 ? 8.0 * pow(t, 4.0) : 1.0;\n}",
        "  r = qio(v_x);",
        None,
    ),
    (
        "pow-negative-base",
        "float qi(float t) { return t > 0.0 ? pow(t, 4.0) : 0.0; }",
        "  r = qi(v_x);",
        None,
    ),
    (
        "pow-negative-base",
        "float att(float dist) { return pow(dist, 2.0); }",
        "  r = att(v_x);",
        None,
    ),
    // A blend of settings a function returns through an `out` parameter (Babylon's generated
    // blocks): 0 once both settings are.
    (
        "division-by-difference",
        "void choose(float a, float b, float c, out float fade) { fade = a * (1.0 - c) + c * b; }",
        "  float q;\n  choose(u_gamma, float(u_sampleCount), v_x, q);\n  r = v_x / q;",
        Some("r = v_x / q;"),
    ),
    // A cross product of two vectors a caller passes as such: the zero vector where they are
    // parallel (a fibre along the normal); tested first, or a normal and a tangent (a mesh's
    // frame, as two per-pixel vectors are taken to be), quiet.
    (
        "normalize-zero",
        "vec3 perp(vec3 n, vec3 fiber) { return normalize(cross(n, fiber)); }",
        "  r = perp(v_pos, v_h).x;",
        Some("vec3 perp(vec3 n, vec3 fiber) { return normalize(cross(n, fiber)); }"),
    ),
    (
        "normalize-zero",
        "vec3 perp(vec3 n, vec3 fiber) {\n  vec3 c = cross(n, fiber);\n  return dot(c, c) > 1e-12 ? normalize(c) : vec3(1.0, 0.0, 0.0);\n}",
        "  r = perp(v_pos, v_h).x;",
        None,
    ),
    (
        "normalize-zero",
        "vec3 bitangent(vec3 normal, vec3 tangent) { return normalize(cross(normal, tangent)); }",
        "  r = bitangent(v_pos, v_h).x;",
        None,
    ),
    // A vector a caller passes as such: a rotation axis, a forward direction, written from
    // itself or not; tested first, or passed a constant, quiet.
    (
        "normalize-zero",
        "mat3 rot(vec3 a, float r) {\n  a = normalize(a);\n  return mat3(a * r, a, a);\n}",
        "  r = rot(v_pos, v_x)[0].x;",
        Some("a = normalize(a);"),
    ),
    (
        "normalize-zero",
        "vec3 fwd(vec3 forward) { return normalize(forward); }",
        "  r = fwd(v_h).x;",
        Some("vec3 fwd(vec3 forward) { return normalize(forward); }"),
    ),
    (
        "normalize-zero",
        "vec3 fwd(vec3 f) {\n  return dot(f, f) > 1e-12 ? normalize(f) : vec3(0.0, 0.0, 1.0);\n}",
        "  r = fwd(v_h).x;",
        None,
    ),
    (
        "normalize-zero",
        "vec3 fwd(vec3 forward) { return normalize(forward); }",
        "  r = fwd(vec3(0.0, 1.0, 0.0)).x;",
        None,
    ),
];

/// A function that returns a value and whose end control can reach without `return` (a lookup
/// that returns from inside its loop): a warning at the statement control leaves after; the
/// same with a fallback `return`, quiet.
#[test]
fn a_function_can_end_without_a_return() {
    let rule = "uninitialised-read";
    let lookup =
        "float pick(int k) {\n  for (int i = 0; i < 4; i++)\n    if (i == k) return float(i);\n}";
    let f = found_with("highp", rule, lookup, "  r = pick(int(v_x));");
    assert_eq!(f, [(W, "for (int i = 0; i < 4; i++)".to_string())], "{f:?}");
    let fallback = "float pick(int k) {\n  for (int i = 0; i < 4; i++)\n    if (i == k) return float(i);\n  return 0.0;\n}";
    let f = found_with("highp", rule, fallback, "  r = pick(int(v_x));");
    assert!(f.is_empty(), "{f:?}");
    let branches = "float sgn(float x) {\n  if (x < 0.0) return -1.0;\n  else return 1.0;\n}";
    let f = found_with("highp", rule, branches, "  r = sgn(v_x);");
    assert!(f.is_empty(), "{f:?}");
}

#[test]
fn what_parameters_make_undefined_is_a_note() {
    let mut failed = Vec::new();
    for (rule, functions, body, at) in PARAMETERS {
        let f = found_with("highp", rule, functions, body);
        let ok = match at {
            Some(line) => f.iter().any(|(s, l)| *s == N && l == line),
            None => f.is_empty(),
        };
        if !ok {
            failed.push(format!("`{functions}` called as `{body}`: {f:?}"));
        }
    }
    assert!(failed.is_empty(), "{}", failed.join("\n"));
}

/// The notes of `rule` in the vertex shader `text`.
fn vertex_notes(rule: &str, text: &str) -> Vec<String> {
    let s = compile(
        SourceFile::new("t.vert", text.to_string()),
        Stage::Vertex,
        &CompileOptions::default(),
    );
    assert!(s.ok() && s.naga.is_some(), "{text}\n{:#?}", s.diagnostics);
    lint(&s, &LintOptions::default().notes(true))
        .into_iter()
        .filter(|d| d.code == rule && d.severity == N)
        .map(|d| d.message)
        .collect()
}

/// A vertex shader's division by its attributes as such: a note (a vertex's data may hold 0);
/// guarded, and the `w` of a position, quiet.
#[test]
fn divisions_by_attributes_are_notes() {
    let notes = |body: &str| {
        let text = format!(
            "#version 300 es\nin vec4 a_pos; in float a_life; in float a_age; in vec4 a_weight;\n\
             in vec3 a_normal; in vec3 a_tangent; uniform mat4 u_world;\n\
             in float a_size; in vec2 a_width; uniform float u_width_t;\n\
             out float v_t; out float width;\n\
             float unpack_mix(vec2 packed, float t) {{ return mix(packed[0], packed[1], t); }}\n\
             float inv_of(float s) {{ return 1.0 / s; }}\n\
             void main() {{\n{body}\n  gl_Position = a_pos;\n}}\n"
        );
        vertex_notes("division-by-difference", &text)
    };
    for body in [
        "  v_t = a_age / a_life;",
        "  v_t = 1.0 / (a_weight.x + a_weight.y + a_weight.z + a_weight.w);",
        // A direction the normal and tangent make, 0 for a mesh without tangents.
        "  v_t = 1.0 / length((u_world * vec4(cross(a_normal, a_tangent), 0.0)).xyz);",
        // An attribute's size is the vertex data's, not the canvas's.
        "  v_t = 0.5 / a_size;",
        // Through a function that unpacks it, and an output the shader keeps it in.
        "  width = unpack_mix(a_width, u_width_t);\n  v_t = a_age / width;",
        // A product with a uniform, through a built-in output and a function's parameter.
        "  gl_PointSize = (a_size + a_age) * u_width_t;\n  v_t = 1.0 / gl_PointSize;",
        "  v_t = inv_of(a_size * u_width_t);",
        // The last of four values packed in an attribute that is no position.
        "  v_t = a_age / a_weight.w;",
    ] {
        assert_eq!(notes(body).len(), 1, "{body}");
    }
    for body in [
        "  v_t = a_age / max(a_life, 1e-4);",
        "  v_t = a_pos.x / a_pos.w;",
        "  v_t = a_age / (a_life + 1.0);",
        "  v_t = 1.0 / max(length((u_world * vec4(cross(a_normal, a_tangent), 0.0)).xyz), 1e-4);",
    ] {
        assert!(notes(body).is_empty(), "{body}: {:?}", notes(body));
    }
}

/// A vertex shader's perspective divide by the `w` of a clip-space position (`gl_Position`, a
/// product with the projection, through a function's parameter): a note (0 on the camera's
/// plane, before clipping); an affine transform's `w`, a tested `w`, a comparison or clamp of
/// the quotient, and a points shader, quiet.
#[test]
fn perspective_divides_in_vertex_shaders_are_notes() {
    let notes = |extra: &str, body: &str| {
        let text = format!(
            "#version 300 es\nuniform mat4 u_projection; uniform mat4 u_view; uniform mat4 u_model;\n\
             in vec3 a_position;\nout vec3 v_ndc;\n\
             vec2 screen(vec4 p) {{ return p.xy / p.w; }}\n\
             void main() {{\n  gl_Position = u_projection * u_view * vec4(a_position, 1.0);\n{body}\n{extra}}}\n"
        );
        vertex_notes("division-by-difference", &text)
    };
    for body in [
        "  v_ndc = gl_Position.xyz / gl_Position.w;",
        "  vec4 clip = u_projection * u_view * u_model * vec4(a_position, 1.0);\n  v_ndc = clip.xyz / clip.w;",
        "  v_ndc = vec3(screen(u_projection * vec4(a_position, 1.0)), 0.0);",
        // A store into another component keeps `w`.
        "  vec4 c = u_projection * vec4(a_position, 1.0);\n  c.z = 0.0;\n  v_ndc = vec3(c.z / c.w);",
    ] {
        assert_eq!(notes("", body).len(), 1, "{body}");
    }
    for body in [
        "  vec4 world = u_model * vec4(a_position, 1.0);\n  v_ndc = world.xyz / world.w;",
        "  v_ndc = gl_Position.w > 1e-6 ? gl_Position.xyz / gl_Position.w : vec3(0.0);",
        "  v_ndc = vec3(step(1.0, gl_Position.z / gl_Position.w));",
        "  gl_Position.z = clamp(gl_Position.z / gl_Position.w, -1.0, 1.0) * gl_Position.w;",
    ] {
        assert!(notes("", body).is_empty(), "{body}: {:?}", notes("", body));
    }
    let points = "  gl_PointSize = 4.0;\n";
    let body = "  v_ndc = gl_Position.xyz / gl_Position.w;";
    assert!(notes(points, body).is_empty(), "{:?}", notes(points, body));
}

/// A direction attribute through a transform: the zero vector for a vertex that holds it; a
/// position, and a vector whose length is tested first, quiet.
#[test]
fn normalized_direction_attributes_are_notes() {
    let notes = |body: &str| {
        let text = format!(
            "#version 300 es\nuniform mat3 u_nm; uniform mat4 u_inverseModel;\n\
             in vec3 a_normal; in vec3 a_position; in vec3 a_next; in vec3 a_tangent;\n\
             out vec3 v_n;\nvoid main() {{\n{body}\n  gl_Position = vec4(a_position, 1.0);\n}}\n"
        );
        vertex_notes("normalize-zero", &text)
    };
    for body in [
        "  v_n = normalize(u_nm * a_normal);",
        "  v_n = normalize(a_normal) * 0.5 + 0.5;",
        // A row vector times the inverse model matrix: its inverse transpose on the normal.
        "  v_n = normalize((vec4(a_normal, 0.0) * u_inverseModel).xyz);",
        // A segment's direction from two positions a vertex holds, scaled.
        "  v_n = normalize((a_next - a_position) * vec3(2.0));",
        // Gram-Schmidt: the zero vector for a zero tangent, or one along the normal.
        "  v_n = normalize(a_tangent - dot(a_tangent, a_normal) * a_normal);",
        // Offsets from the normal by factors of the position (Babylon's fur), normalised in
        // place: the zero vector wherever the normal is, whatever the position.
        "  vec3 t = vec3(a_normal.y, -a_normal.x, 0.0) * (2.0 + fract(a_position.x)) + vec3(-a_normal.z, 0.0, a_normal.x) * a_position.y;\n  t = normalize(t);\n  v_n = t;",
    ] {
        assert_eq!(notes(body).len(), 1, "{body}");
    }
    // NaN from the normalised normal carried on: reported where it is made, once.
    let chain = "  vec3 n = normalize(a_normal);\n  v_n = normalize(cross(n, a_position));";
    assert_eq!(notes(chain).len(), 1, "{chain}: {:?}", notes(chain));
    for quiet in [
        "  v_n = normalize(a_position);",
        // An octahedral decoding is not zero where the attribute is.
        "  vec2 e = a_normal.xy;\n  v_n = normalize(vec3(e, 1.0 - abs(e.x) - abs(e.y)));",
        "  vec3 n = u_nm * a_normal;\n  v_n = dot(n, n) > 1e-12 ? normalize(n) : vec3(0.0, 0.0, 1.0);",
        "  v_n = length(a_normal) > 0.0 ? normalize(a_normal) : vec3(0.0, 0.0, 1.0);",
        // A sum with a position is not zero where the normal is.
        "  v_n = normalize(a_normal * 0.1 + a_position);",
    ] {
        assert!(notes(quiet).is_empty(), "{quiet}");
    }
}

#[test]
fn mediump_overflow_hazards_and_twins() {
    let rule = "mediump-overflow";
    for body in [
        "  float x = u_a * 1000.0;\n  r = x * x;",
        "  r = length(v_pos * 100.0);",
        "  r = exp(t.r * 20.0);",
        // Window coordinates are pixels: squared past 65504 256 pixels from the corner.
        "  vec2 c = gl_FragCoord.xy;\n  r = dot(c, c);",
    ] {
        let f = found("mediump", rule, body);
        assert!(f.iter().any(|(s, _)| *s == W), "{body}: {f:?}");
    }
    for body in [
        "  float x = clamp(u_a, -100.0, 100.0);\n  r = x * x;",
        "  r = length(v_pos * 100.0);",
        "  vec2 c = gl_FragCoord.xy / 4096.0;\n  r = dot(c, c);",
    ] {
        let p = if body.contains("length") {
            "highp"
        } else {
            "mediump"
        };
        assert!(found(p, rule, body).is_empty(), "{body}");
    }
}

/// `mediump-overflow` in bodies with `functions` declared before `main`: each of `notes` is
/// reported in `mediump`, as notes only, and not in `highp`; each of `quiet` is not reported in
/// `mediump`.
fn overflow_notes(functions: &str, notes: &[&str], quiet: &[&str]) {
    let at =
        |precision: &str, body: &str| found_with(precision, "mediump-overflow", functions, body);
    for body in notes {
        let f = at("mediump", body);
        assert!(
            !f.is_empty() && f.iter().all(|(s, _)| *s == N),
            "{body}: {f:?}"
        );
        assert!(at("highp", body).is_empty(), "{body}");
    }
    for body in quiet {
        let f = at("mediump", body);
        assert!(f.is_empty(), "{body}: {f:?}");
    }
}

/// A position a name says is one (`v_pos`, a uniform `u_lightPosition`) is hundreds of units from
/// the origin in a scene measured in pixels or metres: its length in `mediump` is a note (the
/// scene's scale is the program's); one that overflows for modest positions too stays a warning,
/// and a position passed window coordinates keeps their magnitude (a warning); the same in
/// `highp`, and a position the name puts in texture or screen space, quiet.
#[test]
fn scene_positions_in_mediump_are_notes() {
    let functions = "uniform vec3 u_lightPosition; uniform vec2 u_screenPos;\n\
                     float sq(vec2 pixel_position) { return dot(pixel_position, pixel_position); }";
    overflow_notes(
        functions,
        &[
            "  r = length(v_pos);",
            "  vec3 d = normalize(u_lightPosition - v_pos);\n  r = d.x;",
            "  float d = distance(u_lightPosition, v_pos);\n  r = d;",
        ],
        &[
            "  r = length(u_screenPos - v_uv);",
            "  r = length(v_pos * 0.001);",
        ],
    );
    for body in [
        "  r = length(v_pos * 100.0);",
        "  r = sq(gl_FragCoord.xy);",
        // A direction from a position carries no scene's scale: the overflow is the factor's.
        "  vec3 d = normalize(v_pos * 0.001);\n  r = length(d * 1000.0);",
    ] {
        let f = found_with("mediump", "mediump-overflow", functions, body);
        assert!(f.iter().any(|(s, _)| *s == W), "{body}: {f:?}");
    }
}

/// A time a name says is the animation's (`iTime`, `u_time`) reaches thousands of seconds on a
/// page left open an hour: what only that reaches in `mediump` is a note (how long a page stays
/// open is the program's to know); a time wrapped by the shader, a time scale, and `highp`, quiet.
#[test]
fn an_hour_of_animation_time_in_mediump_is_a_note() {
    overflow_notes(
        "uniform float iTime; uniform float u_timeScale;",
        &[
            "  r = iTime * 30.0;",
            "  for (mediump int j = 0; j < 20; j++) {\n    r += sin(float(j) * iTime * 0.05);\n  }",
        ],
        &[
            "  r = fract(iTime) * 30.0;",
            "  r = u_timeScale * 30.0;",
            "  r = mod(iTime, 60.0) * 30.0;",
        ],
    );
}

/// A ray march's distance grows by a step proportional to it for a fixed number of iterations
/// (`t += max(0.075, 0.02 * t)`, 115 steps: `t` < 33): bounded, a lattice index 113 times a
/// position along the ray overflows `mediump` for ordinary values — in `main` and through a
/// function's parameter and result; the same march to a distance that stays small (fewer
/// iterations, a smaller index factor) and a loop whose count a uniform sets (unbounded, not
/// reported), quiet.
#[test]
fn a_ray_march_with_a_fixed_count_of_steps_is_bounded() {
    let functions = "uniform int u_steps;\n\
        float lattice(vec3 p) { return floor(p.x) + floor(p.y) * 57.0 + FACTOR * floor(p.z); }\n\
        float march(vec3 rd) { float t = 0.0;\n\
          for (int i = 0; i < 80; i++) { if (t > 900.0) break; t += max(0.075, 0.02 * t); }\n\
          for (int i = 0; i < 35; i++) { t += max(0.075, 0.02 * t); }\n\
          return t; }\n";
    let march = |factor: &str, body: &str| {
        let functions = functions.replace("FACTOR", factor);
        found_with("mediump", "mediump-overflow", &functions, body)
    };
    for body in [
        "  r = lattice(v_n + march(v_n) * normalize(v_n));",
        "  float d = 1.0;\n  for (int k = 0; k < 115; k++) { d = d + 0.02 * d + 0.075; }\n  r = d * 2000.0;",
        // A weight that shrinks starts at its largest.
        "  float z = 100.0;\n  for (int k = 0; k < 5; k++) { r += z * 1000.0; z *= 0.5; }",
    ] {
        let f = march("2000.0", body);
        assert!(f.iter().any(|(s, _)| *s == W), "{body}: {f:?}");
    }
    for body in [
        "  r = lattice(v_n + march(v_n) * normalize(v_n));",
        "  float d = 1.0;\n  for (int k = 0; k < 20; k++) { d += max(0.075, 0.02 * d); }\n  r = d * 2000.0;",
        "  float d = 1.0;\n  for (int k = 0; k < 1000; k++) { if (k >= u_steps) break; d += max(0.075, 0.02 * d); }\n  r = d;",
    ] {
        let f = march("1.0", body);
        assert!(f.is_empty(), "{body}: {f:?}");
    }
}

/// A white point, a filter's size, a stroke's size, a fraction and a grid's step
/// (`floor(x / s) * s`) are settings a user may set to 0: a division by one (or by a multiple
/// of one) is a note naming it. The same divisions after `if (n == 0) return;`, by a size the
/// host sets, `mod` and a quotient snapped to another step are quiet.
#[test]
fn white_points_sizes_fractions_and_grid_steps_are_settings() {
    let functions =
        "uniform float u_white; uniform int u_filterSize; uniform float u_strokeSize;\n\
        uniform float _Glow_Fraction_; uniform float u_viewportSize; uniform float u_pitch;\n";
    let division = |body: &str| found_with("highp", "division-by-difference", functions, body);
    for body in [
        "  r = t.r * (1.0 + t.r / u_white);",
        "  float sigma = float(u_filterSize);\n  r = exp(-v_x / (2.0 * sigma * sigma));",
        "  r = v_x / u_strokeSize;",
        "  r = clamp((1.0 - v_x) / _Glow_Fraction_, 0.0, 1.0);",
        // A grid's step, whatever its name: a pixelation's cell.
        "  r = floor(v_x / u_pitch) * u_pitch;",
    ] {
        let f = division(body);
        assert_eq!(f.len(), 1, "{body}: {f:?}");
        assert_eq!(f[0].0, N, "{body}: {f:?}");
    }
    for body in [
        "  if (u_filterSize == 0) { o = t; return; }\n  r = v_x / float(u_filterSize);",
        "  if (u_filterSize != 0) { r = v_x / float(u_filterSize); }",
        "  r = v_x / u_viewportSize;",
        "  r = mod(v_x, u_pitch) + floor(v_x / u_pitch) * u_viewportSize;",
        "  r = floor(v_x / max(u_pitch, 1e-4)) * u_pitch;",
    ] {
        let f = division(body);
        assert!(f.is_empty(), "{body}: {f:?}");
    }
}

/// A pixel's offset from a centre the host sets (`v_uv - u_center`, scaled by a size, written
/// component by component, or from the middle `0.5`) is the zero vector at the pixel on the
/// centre — exactly, for (0.5, 0.5) on a target of odd size: a warning on `normalize` and on a
/// division by its length, a note on `pow` of its length with a uniform exponent. An offset from a uniform not named as a centre, a position's offset,
/// and a guarded offset, quiet.
#[test]
fn a_pixel_offset_from_a_centre_is_a_note() {
    let functions = "uniform vec2 u_center; uniform vec2 u_offset; uniform vec2 u_size;";
    let at = |rule: &str, body: &str| found_with("highp", rule, functions, body);
    // `pow` of its length with a uniform exponent is a note naming the uniform, as for a base
    // 0 over a region.
    for (rule, body, severity) in [
        ("normalize-zero", "  r = normalize(v_uv - u_center).x;", W),
        (
            "normalize-zero",
            "  vec2 d = vec2(v_uv.x - u_center.x, v_uv.y - u_center.y);\n  r = normalize(d).y;",
            W,
        ),
        ("normalize-zero", "  r = normalize(v_uv - 0.5).x;", W),
        // From the middle, flipped, scaled by a uniform, in a wider vector with a zero
        // (Cesium's lens flare).
        (
            "normalize-zero",
            "  vec2 fl = vec2(1.0) - v_uv;\n  vec2 g = (vec2(0.5) - fl) * u_a;\n  r = normalize(vec3(g, 0.0)).x + normalize(g).y;",
            W,
        ),
        (
            "division-by-difference",
            "  vec2 c = v_uv * u_size;\n  c -= u_center * u_size;\n  float d = length(c);\n  r = u_a / d;",
            W,
        ),
        ("pow-zero-base", "  r = pow(length(v_uv - u_center), u_a);", N),
        (
            "pow-zero-base",
            "  vec2 c = vec2(v_uv.x - u_center.x, v_uv.y - u_center.y);\n  float d = sqrt(c.x * c.x + c.y * c.y);\n  r = pow(d, u_a);",
            N,
        ),
    ] {
        let f = at(rule, body);
        assert!(
            !f.is_empty() && f.iter().all(|(s, _)| *s == severity),
            "{body}: {f:?}"
        );
    }
    for (rule, body) in [
        ("normalize-zero", "  r = normalize(v_uv - u_offset).x;"),
        ("normalize-zero", "  r = normalize(v_pos.xy - u_center).x;"),
        // One component of the offset is 0 on a line of pixels, and a vector scaled per pixel
        // is another vector.
        (
            "normalize-zero",
            "  vec2 g = vec2(0.5) - v_uv;\n  r = normalize(vec3(g.x, 0.0, 0.0)).x + normalize(g * v_x).y;",
        ),
        (
            "normalize-zero",
            "  vec2 d = v_uv - u_center;\n  r = dot(d, d) > 1e-12 ? normalize(d).x : 0.0;",
        ),
        (
            "division-by-difference",
            "  float d = length(v_uv - u_center);\n  r = u_a / max(d, 1e-4);",
        ),
        ("pow-zero-base", "  r = pow(length(v_uv - u_offset), u_a);"),
        (
            "pow-zero-base",
            "  r = pow(max(length(v_uv - u_center), 1e-4), u_a);",
        ),
    ] {
        let f = at(rule, body);
        assert!(f.is_empty(), "{body}: {f:?}");
    }
    // A vertex on the centre is one vertex, not a pixel of every frame.
    let vertex = "#version 300 es\nuniform vec2 u_center; uniform float u_a;\nin vec2 a_uv;\nout float v_k;\n\
        void main() { v_k = pow(length(a_uv - u_center), u_a) + pow(length(a_uv - 0.5), u_a); gl_Position = vec4(a_uv, 0.0, 1.0); }\n";
    let f = vertex_notes("pow-zero-base", vertex);
    assert!(f.is_empty(), "{f:?}");
}

/// The animation's time in a `mediump` uniform (by the default or declared), in a block too: a
/// note with a fix to `highp`; `highp`, a vertex shader's default, another quantity's name
/// (`deltaTime`) and a time the shader never reads, quiet.
#[test]
fn a_mediump_animation_time_is_a_note() {
    let rule = "mediump-time";
    let frag = |decls: &str, precision: &str| {
        let text = format!(
            "#version 300 es\nprecision {precision} float;\n{decls}\nout vec4 o;\n\
             void main() {{ o = vec4(sin(t * 3.0)); }}\n"
        );
        let s = super::compiled("t.frag", &text);
        lint(&s, &LintOptions::default().notes(true))
            .into_iter()
            .filter(|d| d.code == rule)
            .map(|d| (d.severity, d.fix.map(|f| f.edits[0].replacement.clone())))
            .collect::<Vec<_>>()
    };
    let highp = Some("highp ".to_string());
    assert_eq!(
        frag("uniform float iTime;\n#define t iTime", "mediump"),
        [(N, highp.clone())]
    );
    assert_eq!(
        frag("uniform lowp float u_time;\n#define t u_time", "highp"),
        [(N, Some("highp".to_string()))]
    );
    assert_eq!(
        frag(
            "uniform Frame { float uTime; };\n#define t uTime",
            "mediump"
        ),
        [(N, highp)]
    );
    for quiet in [
        ("uniform highp float iTime;\n#define t iTime", "mediump"),
        ("uniform float iTime;\n#define t iTime", "highp"),
        ("uniform float deltaTime;\n#define t deltaTime", "mediump"),
        ("uniform float iTime;\n#define t 1.0", "mediump"),
    ] {
        assert!(frag(quiet.0, quiet.1).is_empty(), "{quiet:?}");
    }
    let vertex =
        "#version 300 es\nuniform float iTime;\nvoid main() { gl_Position = vec4(iTime); }\n";
    assert!(vertex_notes(rule, vertex).is_empty());
}

/// A length declared `lowp` (range (-2, 2) at the minimum): a note at the declaration; the
/// same declared `mediump`, a `lowp` colour, a mix factor named for a length, and a `lowp`
/// that only the default precision gives, quiet.
#[test]
fn lowp_lengths_are_notes() {
    let notes = |text: &str| vertex_notes("mediump-overflow", text);
    let shader = |decl: &str| {
        format!(
            "#version 300 es\n{decl}\nin vec4 a_pos;\nout float v;\n\
             void main() {{\n  v = dot(vec4(1.0), vec4(a_x));\n  gl_Position = a_pos;\n}}\n"
        )
    };
    for decl in [
        "in lowp vec4 a_pattern_from;\n#define a_x a_pattern_from",
        "in lowp float a_floorwidth;\n#define a_x a_floorwidth",
    ] {
        assert_eq!(notes(&shader(decl)).len(), 1, "{decl}");
    }
    for decl in [
        "in mediump vec4 a_pattern_from;\n#define a_x a_pattern_from",
        "in lowp vec4 a_color;\n#define a_x a_color",
        "uniform lowp float u_width_t;\n#define a_x u_width_t",
        "precision lowp float;\nin float a_floorwidth;\n#define a_x a_floorwidth",
    ] {
        assert!(notes(&shader(decl)).is_empty(), "{decl}");
    }
}

/// Every kind of value the suite covers has at least one hazard per rule that can meet it.
#[test]
fn every_rule_has_a_hazard_and_a_twin() {
    for r in essl_lint::RULES {
        // `mediump-overflow` and `mediump-time` need a precision the suite's `highp` shader
        // lacks: their own tests hold their hazards and twins.
        if matches!(
            r.id,
            "unused-essl-allow" | "mediump-overflow" | "mediump-time"
        ) {
            continue;
        }
        assert!(HAZARDS.iter().any(|h| h.0 == r.id), "{}: no hazard", r.id);
        assert!(GUARDED.iter().any(|g| g.0 == r.id), "{}: no twin", r.id);
    }
}

/// The corpora of `docs/lints/corpus.md`, where `ESSL_LINT_CORPORA` names the folder that
/// holds them (`old/` as `scripts/lint-corpus/fetch.sh` builds it, `fresh/` as
/// `scripts/lint-corpus/fetch-fresh.sh` does).
fn corpora() -> Option<std::path::PathBuf> {
    let dir = std::path::PathBuf::from(std::env::var_os("ESSL_LINT_CORPORA")?);
    Some(dir)
}

fn collapse(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// Input-dependent findings of the triage tables that a rule leaves out on purpose since they
/// were classified, or reports on other lines: (rule, repository, source line, why).
const DROPPED: &[(&str, &str, &str, &str)] = &[
    (
        "normalize-zero",
        "npm:lygia",
        "return saturate(1.0 +",
        "moved, not dropped: since macro arguments keep their spans, the note is on each of the two `normalize` calls inside `saturate(…)`, not on the line the call starts",
    ),
    (
        "division-by-difference",
        "kantedal/pathtracer-webgl2",
        "float TP = Tr / (1.0 - P);",
        "a per-pixel difference (P follows a Fresnel term of the view angle): 0 at isolated pixels at most",
    ),
    (
        "normalize-zero",
        "npm:lygia",
        "float bac = saturate(dot(m.normal, normalize(vec3(-lig.x, 0.0, -lig.z)))) * saturate(1.0 - m.position.y);",
        "without LIGHT_DIRECTION the light direction varies per pixel: straight above at isolated points",
    ),
];

/// Whether a rule's findings are notes by default (a real one of such a rule is a note too).
fn notes_only(rule: &str) -> bool {
    essl_lint::rule(rule).is_some_and(|r| r.default_level == essl_lint::Level::Note)
}

/// The message of a `mediump-overflow` finding that only positions of a large scene reach: a note,
/// since the shader does not say whether its scene is measured in pixels or in metres.
const SCALE_NOTE: &str = "in a scene hundreds of units across";

/// The message of a `pow-zero-base` note on an exponent that is a uniform as such, undefined when
/// the uniform is 0: a note, since whether the host's default is 0 is the program's to know.
const UNIFORM_ZERO_NOTE: &str = "undefined (NaN) when `";

/// Every finding classified `real`, `rounding` or `input` in a corpus's triage table is still
/// reported at its source line (in the shader as compiled or in a configuration of its
/// `#ifdef`s, as a check lints them by default): a real one as a warning, the others at least as a note (but
/// for [`DROPPED`]). A real one may be a note where the rule says the scale that reaches it is the
/// program's to know ([`SCALE_NOTE`]: positions in a scene measured in pixels; [`UNIFORM_ZERO_NOTE`]:
/// a uniform exponent whose default is 0), or where the rule's findings are all notes
/// ([`notes_only`]). Runs where `ESSL_LINT_CORPORA` names the corpora (`scripts/test.sh` fetches
/// the fresh one; the old one needs GitHub, and is checked where present); skipped otherwise
/// (they live outside the repository).
#[test]
fn every_classified_true_positive_is_still_reported() {
    let Some(dir) = corpora() else {
        eprintln!("skipped: set ESSL_LINT_CORPORA to the folder holding fresh/ (and old/)");
        return;
    };
    let docs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/lints");
    let mut missing = Vec::new();
    let mut checked = 0;
    for (corpus, table) in [
        ("old", "corpus-triage.tsv"),
        ("fresh", "corpus-fresh-triage.tsv"),
    ] {
        let root = dir.join(corpus);
        if corpus == "old" && !root.join("manifest.jsonl").exists() {
            eprintln!("skipped the old corpus: no {}", root.display());
            continue;
        }
        let manifest = std::fs::read_to_string(root.join("manifest.jsonl"))
            .unwrap_or_else(|e| panic!("{}: {e}", root.display()));
        let triage = std::fs::read_to_string(docs.join(table)).expect("a triage table");
        // (rule, repository, line or "*", collapsed source line, class)
        let rows: Vec<[String; 5]> = triage
            .lines()
            .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
            .map(|l| {
                let p: Vec<&str> = l.split('\t').collect();
                [
                    p[0].to_string(),
                    p[1].to_string(),
                    p[2].to_string(),
                    collapse(p[3]),
                    p[4].to_string(),
                ]
            })
            .filter(|r| ["real", "rounding", "input"].contains(&r[4].as_str()))
            .filter(|r| {
                !DROPPED
                    .iter()
                    .any(|d| d.0 == r[0] && d.1 == r[1] && collapse(d.2) == r[3])
            })
            .collect();
        // The findings of every shader whose text holds one of those lines.
        let mut found: Vec<(String, String, usize, String, Severity, bool)> = Vec::new();
        for entry in manifest.lines().filter(|l| !l.trim().is_empty()) {
            let e: serde_json::Value = serde_json::from_str(entry).expect("a JSON line");
            let repo = e["repo"].as_str().unwrap_or_default();
            let file = e["file"].as_str().unwrap_or_default();
            let Ok(text) = std::fs::read_to_string(root.join(file)) else {
                continue;
            };
            let lines: Vec<String> = text.lines().map(collapse).collect();
            if !rows
                .iter()
                .any(|r| r[1] == repo && lines.iter().any(|l| *l == r[3]))
            {
                continue;
            }
            let stage = if e["stage"].as_str() == Some("vertex") {
                Stage::Vertex
            } else {
                Stage::Fragment
            };
            let s = compile(
                SourceFile::new(file, text.as_str()),
                stage,
                &CompileOptions::default(),
            );
            if !s.ok() || s.naga.is_none() {
                continue;
            }
            // The configurations its `#ifdef`s select too, as a check lints them by default.
            let options = LintOptions::default().notes(true);
            let compile_options = CompileOptions::default();
            let mut all = lint(&s, &options);
            let more = essl_lint::variants::lint_text(
                &s,
                &compile_options,
                &options,
                &all,
                essl_lint::variants::DEFAULT,
            );
            all.extend(more.into_iter().map(|f| f.diagnostic));
            for d in all {
                let line = s.file.line_col(d.span.start).line as usize;
                let source = lines.get(line - 1).cloned().unwrap_or_default();
                found.push((
                    d.code.to_string(),
                    repo.to_string(),
                    line,
                    source,
                    d.severity,
                    d.message.contains(SCALE_NOTE) || d.message.contains(UNIFORM_ZERO_NOTE),
                ));
            }
        }
        for r in &rows {
            checked += 1;
            let ok = found
                .iter()
                .any(|(rule, repo, line, source, severity, scale)| {
                    *rule == r[0]
                        && *repo == r[1]
                        && *source == r[3]
                        && (r[2] == "*" || r[2] == line.to_string())
                        && (r[4] != "real"
                            || *severity == Severity::Warning
                            || *scale
                            || notes_only(rule))
                });
            if !ok {
                missing.push(format!("{corpus}: {} {} `{}` ({})", r[0], r[1], r[3], r[4]));
            }
        }
    }
    assert!(checked > 0);
    assert!(
        missing.is_empty(),
        "no longer reported:\n{}",
        missing.join("\n")
    );
}

/// A parameter takes its name's word only where callers pass an input as such (the way a
/// library function is called from a harness, or a helper with a varying): `rgb` a colour, where
/// black is ordinary, `normal` a unit normal, along an axis over whole faces.
#[test]
fn parameters_named_for_a_colour_or_a_normal() {
    let helpers = "float mmin(vec3 v) { return min(v.x, min(v.y, v.z)); }\n\
        vec3 toCmy(vec3 rgb) { float k = mmin(1.0 - rgb); return (1.0 - rgb - k) / (1.0 - k); }\n\
        float azimuth(vec3 normal) { return atan(normal.y, normal.x); }\n\
        float polar(vec3 normal) { return acos(normal.z); }\n";
    let run = |call: &str| {
        let text = format!(
            "#version 300 es\nprecision highp float;\nin vec3 v_a; in vec3 v_pos;\nuniform vec3 u_eye;\n\
             out vec4 o;\n{helpers}void main() {{ {call} }}\n"
        );
        let s = super::compiled("t.frag", &text);
        let mut codes: Vec<&str> = lint(&s, &LintOptions::default().notes(true))
            .into_iter()
            .map(|d| d.code)
            .collect();
        codes.sort();
        codes
    };
    assert_eq!(
        run("o = vec4(toCmy(v_a), azimuth(v_a) + polar(v_a));"),
        ["acos-domain", "division-by-difference", "domain-atan2"]
    );
    // A view direction passed under the name: per pixel, the axis at isolated pixels; `acos` of
    // its component is rounding's hazard still.
    assert_eq!(
        run("vec3 d = normalize(v_pos - u_eye); o = vec4(azimuth(d) + polar(d));"),
        ["acos-domain"]
    );
}

/// A finding in a macro's replacement list underlines the invocation and labels the macro's
/// `#define`, as the front end's errors there do.
#[test]
fn a_finding_in_a_macro_labels_its_define() {
    let text = "#version 300 es\nprecision highp float;\nuniform sampler2D iTex;\nin vec2 v_uv;\n\
                out vec4 o;\n#define T texture(iTex, v_uv).x\n\
                void main() {\n  float f = 0.0;\n  if (v_uv.x > 0.5) { f = T; }\n  o = vec4(f);\n}\n";
    let s = super::compiled("t.frag", text);
    let found = lint(&s, &LintOptions::default().notes(true));
    let d = found
        .iter()
        .find(|d| d.code == "non-uniform-derivative")
        .expect("the lookup under a per-pixel branch");
    assert_eq!(s.file.slice(d.span), "T");
    let labels: Vec<(&str, &str)> = d
        .secondary
        .iter()
        .map(|l| (s.file.slice(l.span), l.message.as_str()))
        .collect();
    assert!(
        labels.contains(&("T", "in this expansion of `T`, defined here")),
        "{labels:?}"
    );
}

#[test]
fn a_lookup_in_a_straight_function_called_under_a_varying_branch() {
    // The only lookup is in a function without a branch, the only branch in `main`: the check
    // that skips shaders lacking either looks at the whole module.
    let shader = |body: &str| {
        format!(
            "#version 300 es\nprecision highp float;\nuniform sampler2D u_tex;\nin vec2 v_uv;\n\
             out vec4 o;\nfloat atlas(vec2 p) {{ return texture(u_tex, p).r; }}\n\
             void main() {{\n  float r = 0.0;\n{body}\n  o = vec4(r);\n}}\n"
        )
    };
    let codes = |body: &str| -> Vec<(Severity, u32)> {
        let s = super::compiled("t.frag", &shader(body));
        lint(&s, &LintOptions::default().notes(true))
            .into_iter()
            .filter(|d| d.code == "non-uniform-derivative")
            .map(|d| (d.severity, s.file.line_col(d.span.start).line))
            .collect()
    };
    assert_eq!(codes("  if (v_uv.x > 0.5) { r = atlas(v_uv); }"), [(W, 6)]);
    // The same call outside the branch: nothing.
    assert!(codes("  r = atlas(v_uv);\n  if (v_uv.x > 0.5) { r = 0.0; }").is_empty());
}

#[test]
fn a_lookup_in_a_function_called_after_a_discard_is_a_note() {
    // Cesium's billboard reads its SDF atlas in `getDistance`, called after the depth test's
    // `discard`; the lookup in a function the helper calls is reached too.
    let functions = "float atlas(vec2 p) { return texture(u_tex, p).r; }\n\
                     float dist(vec2 p) { return atlas(p * 2.0); }";
    let notes = found_with(
        "highp",
        "non-uniform-derivative",
        functions,
        "  if (t.a < 0.5) discard;\n  r = dist(v_uv);",
    );
    assert_eq!(
        notes,
        [(
            N,
            "float atlas(vec2 p) { return texture(u_tex, p).r; }".to_string()
        )]
    );
    // Called before the `discard`, or after one every pixel of the draw takes: nothing.
    for body in [
        "  r = dist(v_uv);\n  if (t.a < 0.5) discard;",
        "  if (u_on) discard;\n  r = dist(v_uv);",
    ] {
        assert!(
            found_with("highp", "non-uniform-derivative", functions, body).is_empty(),
            "{body}"
        );
    }
}

#[test]
fn a_struct_member_written_on_some_paths_only() {
    // p5's `light()`: the specular term is written only where `uSpecular` is set, and the
    // caller reads it.
    let functions = "struct Light { float specular; float diffuse; };\n\
                     Light light(vec3 l) {\n  Light lr;\n  if (u_on) lr.specular = max(l.z, 0.0);\n  \
                     lr.diffuse = max(l.x, 0.0);\n  return lr;\n}";
    let found = found_with(
        "highp",
        "uninitialised-read",
        functions,
        "  Light x = light(n);\n  r = x.specular + x.diffuse;",
    );
    assert_eq!(found, [(W, "return lr;".to_string())]);
    let text = shader_with(
        "highp",
        functions,
        "  Light x = light(n);\n  r = x.specular;",
    );
    let messages: Vec<String> = lint(&super::compiled("t.frag", &text), &LintOptions::default())
        .into_iter()
        .filter(|d| d.code == "uninitialised-read")
        .map(|d| d.message)
        .collect();
    assert_eq!(
        messages,
        ["variable `lr` is read whole before `lr.specular` is written on some path"]
    );
    // A member no path writes, read by itself.
    let found = found_with(
        "highp",
        "uninitialised-read",
        "struct Light { float specular; float diffuse; };",
        "  Light x;\n  x.diffuse = 1.0;\n  r = x.specular;",
    );
    assert_eq!(found, [(W, "r = x.specular;".to_string())]);
    // Written on every path; and a struct filled in part, passed whole (three.js's materials).
    for (functions, body) in [
        (
            "struct Light { float specular; float diffuse; };",
            "  Light x;\n  x.specular = 0.0;\n  if (u_on) x.specular = 1.0;\n  x.diffuse = 1.0;\n  \
             Light y = x;\n  r = y.specular;",
        ),
        (
            "struct Light { float specular; float diffuse; };\n\
             float use(Light m) { return m.diffuse; }",
            "  Light x;\n  x.diffuse = 1.0;\n  r = use(x);",
        ),
    ] {
        assert!(
            found_with("highp", "uninitialised-read", functions, body).is_empty(),
            "{body}"
        );
    }
}
