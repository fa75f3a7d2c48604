//! Each rule on small shaders: what it reports (and where), and what it must not report.

use essl::diagnostic::{apply_fixes, Applicability, Diagnostic, Severity};
use essl::source::SourceFile;
use essl::{compile, CompileOptions, Shader, Stage};
use essl_lint::{lint, Level, LintOptions};

/// A fragment shader with the usual declarations around `body` (statements of `main`) and
/// `decls` (declarations before it).
fn frag(precision: &str, decls: &str, body: &str) -> String {
    format!(
        "#version 300 es\nprecision {precision} float;\n\
         uniform float u_a; uniform float u_b; uniform float u_k; uniform vec3 u_up; uniform vec3 u_dir;\n\
         uniform vec3 u_eye; uniform vec3 u_target; uniform mat4 u_m; uniform sampler2D u_tex;\n\
         in vec3 v_n; in vec3 v_h; in vec3 v_t; in vec3 v_pos; in float v_x; in vec2 v_uv;\n\
         out vec4 o;\n{decls}\nvoid main() {{\n  float r = 0.0;\n{body}\n  o = vec4(r);\n}}\n"
    )
}

fn compiled(text: &str) -> Shader {
    super::compiled("t.frag", text)
}

/// The findings: (rule, the text of the span).
fn findings(text: &str) -> Vec<(&'static str, String)> {
    let s = compiled(text);
    lint(&s, &LintOptions::default())
        .iter()
        .map(|d| (d.code, s.file.slice(d.span).to_string()))
        .collect()
}

fn codes_of(text: &str, rule: &str) -> Vec<String> {
    findings(text)
        .into_iter()
        .filter(|(c, _)| *c == rule)
        .map(|(_, t)| t)
        .collect()
}

/// `body` gets exactly the findings `expected` (span texts) of `rule`.
#[track_caller]
fn reports(rule: &str, precision: &str, decls: &str, body: &str, expected: &[&str]) {
    let text = frag(precision, decls, body);
    assert_eq!(codes_of(&text, rule), expected, "{rule} in:\n{text}");
}

/// `body` gets exactly the notes `expected` (span texts) of `rule`, when notes are asked for;
/// they are not reported otherwise.
#[track_caller]
fn notes(rule: &str, precision: &str, decls: &str, body: &str, expected: &[&str]) {
    let text = frag(precision, decls, body);
    let s = compiled(&text);
    let found: Vec<String> = lint(&s, &LintOptions::default().notes(true))
        .iter()
        .filter(|d| d.code == rule && d.severity == Severity::Note)
        .map(|d| s.file.slice(d.span).to_string())
        .collect();
    assert_eq!(found, expected, "{rule} notes in:\n{text}");
    assert!(
        codes_of(&text, rule).is_empty(),
        "notes are not reported by default:\n{text}"
    );
}

/// `body` has no finding of `rule`.
#[track_caller]
fn clean(rule: &str, precision: &str, decls: &str, body: &str) {
    reports(rule, precision, decls, body, &[]);
}

/// Applying every suggested fix makes the shader clean of `rule`.
#[track_caller]
fn fixes_clear(rule: &str, precision: &str, decls: &str, body: &str) {
    let text = frag(precision, decls, body);
    let s = compiled(&text);
    let found: Vec<Diagnostic> = lint(&s, &LintOptions::default())
        .into_iter()
        .filter(|d| d.code == rule)
        .collect();
    assert!(!found.is_empty());
    let (fixed, n) = apply_fixes(&text, &found, Applicability::Suggested);
    assert_eq!(n, found.len(), "every finding has a fix");
    assert!(
        codes_of(&fixed, rule).is_empty(),
        "still reported after the fix:\n{fixed}"
    );
}

// ----- pow-negative-base -----

#[test]
fn pow_of_a_dot_product_may_have_a_negative_base() {
    let rule = "pow-negative-base";
    reports(
        rule,
        "highp",
        "",
        "  r = pow(dot(normalize(v_n), normalize(v_h)), u_k);",
        &["dot(normalize(v_n), normalize(v_h))"],
    );
    reports(
        rule,
        "highp",
        "",
        "  r = pow(sin(v_x), 2.0);",
        &["sin(v_x)"],
    );
    reports(
        rule,
        "highp",
        "",
        "  r = pow(u_a - u_b, 2.0);",
        &["u_a - u_b"],
    );
    // Through a local, and guarded by a test of another dot product (article 001).
    reports(
        rule,
        "mediump",
        "",
        "  vec3 n = normalize(v_n);\n  float light = dot(n, normalize(v_t));\n  if (light > 0.0) {\n    float d = dot(n, normalize(v_h));\n    r = pow(d, u_k);\n  }",
        &["d"],
    );
    fixes_clear(
        rule,
        "highp",
        "",
        "  r = pow(dot(normalize(v_n), normalize(v_h)), u_k);",
    );
}

#[test]
fn pow_of_a_clamped_or_external_base_is_fine() {
    let rule = "pow-negative-base";
    clean(
        rule,
        "highp",
        "",
        "  r = pow(max(dot(normalize(v_n), normalize(v_h)), 0.0), u_k);",
    );
    clean(
        rule,
        "highp",
        "",
        "  r = pow(clamp(dot(v_n, v_h), 0.0, 1.0), 5.0);",
    );
    clean(
        rule,
        "highp",
        "",
        "  float d = dot(v_n, v_h);\n  float k = max(d, 0.0);\n  r = pow(k, u_k);",
    );
    clean(rule, "highp", "", "  r = pow(u_a, 2.0) + pow(v_x, 3.0);");
    clean(
        rule,
        "highp",
        "",
        "  r = pow(texture(u_tex, v_uv).r * u_a, 2.2);",
    );
    clean(rule, "highp", "", "  float x = dot(v_n, v_h);\n  r = pow(x * x, 0.5) + pow(abs(x), 3.0) + pow(length(v_n), 2.0) + pow(exp(x), 2.0);");
    clean(
        rule,
        "highp",
        "",
        "  r = pow(1.0 - clamp(dot(v_n, v_h), 0.0, 1.0), 5.0);",
    );
}

// ----- pow-zero-base -----

#[test]
fn pow_of_zero_to_a_non_positive_power() {
    let rule = "pow-zero-base";
    reports(
        rule,
        "highp",
        "",
        "  r = pow(max(dot(v_n, v_h), 0.0), 0.0);",
        &["max(dot(v_n, v_h), 0.0)"],
    );
    reports(
        rule,
        "highp",
        "",
        "  r = pow(max(v_x - 1.0, 0.0), v_x - 1.0);",
        &["max(v_x - 1.0, 0.0)"],
    );
    // An exponent only one uniform makes non-positive: a note naming it.
    notes(
        rule,
        "highp",
        "",
        "  r = pow(max(v_x - 1.0, 0.0), u_k - 1.0);",
        &["max(v_x - 1.0, 0.0)"],
    );
    fixes_clear(
        rule,
        "highp",
        "",
        "  r = pow(max(v_x - 1.0, 0.0), v_x - 1.0);",
    );
}

#[test]
fn pow_with_a_uniform_or_positive_exponent_is_fine() {
    let rule = "pow-zero-base";
    clean(
        rule,
        "highp",
        "",
        "  r = pow(max(dot(v_n, v_h), 0.0), u_k);",
    );
    clean(
        rule,
        "highp",
        "",
        "  r = pow(max(dot(v_n, v_h), 0.0), 16.0);",
    );
    clean(
        rule,
        "highp",
        "",
        "  r = pow(max(dot(v_n, v_h), 1e-4), u_k - 1.0);",
    );
    clean(rule, "highp", "", "  r = pow(max(v_x, 0.0) + 1.0, -1.0);");
}

// ----- acos-domain / asin-domain -----

#[test]
fn acos_of_a_dot_product_of_unit_vectors() {
    let rule = "acos-domain";
    reports(
        rule,
        "highp",
        "",
        "  r = acos(dot(normalize(v_n), normalize(v_h)));",
        &["dot(normalize(v_n), normalize(v_h))"],
    );
    // Article 003: the up vector is a uniform, not known to be unit length.
    reports(
        rule,
        "highp",
        "",
        "  float upCos = dot(normalize(v_n), u_up);\n  r = acos(upCos);",
        &["upCos"],
    );
    fixes_clear(
        rule,
        "highp",
        "",
        "  r = acos(dot(normalize(v_n), normalize(v_h)));",
    );
}

#[test]
fn acos_of_a_clamped_value_or_uniform_is_fine() {
    let rule = "acos-domain";
    clean(
        rule,
        "highp",
        "",
        "  r = acos(clamp(dot(normalize(v_n), normalize(v_h)), -1.0, 1.0));",
    );
    clean(
        rule,
        "highp",
        "",
        "  r = acos(u_a) + acos(0.5) + acos(cos(v_x));",
    );
    clean(
        rule,
        "highp",
        "",
        "  r = acos(min(max(dot(v_n, v_h), -1.0), 1.0));",
    );
}

#[test]
fn asin_domain() {
    let rule = "asin-domain";
    reports(
        rule,
        "highp",
        "",
        "  r = asin(normalize(v_pos).y);",
        &["normalize(v_pos).y"],
    );
    reports(rule, "highp", "", "  r = asin(v_x * 2.0);", &["v_x * 2.0"]);
    clean(
        rule,
        "highp",
        "",
        "  r = asin(clamp(normalize(v_pos).y, -1.0, 1.0)) + asin(v_x) + asin(sin(v_x));",
    );
    fixes_clear(rule, "highp", "", "  r = asin(normalize(v_pos).y);");
}

// ----- smoothstep-edges -----

#[test]
fn smoothstep_with_uniform_edges() {
    let rule = "smoothstep-edges";
    reports(
        rule,
        "highp",
        "",
        "  r = smoothstep(u_a, u_b, v_x);",
        &["smoothstep(u_a, u_b, v_x)"],
    );
    // Edges only one uniform can make equal or swapped: a note naming it.
    notes(
        rule,
        "highp",
        "",
        "  r = smoothstep(0.0, u_b, v_x);",
        &["smoothstep(0.0, u_b, v_x)"],
    );
    // Edges that reach a function through its parameters (three.js getSpotAttenuation).
    reports(
        rule,
        "highp",
        "float atten(const in float c, const in float p, const in float a) { return smoothstep(c, p, a); }",
        "  r = atten(u_a, u_b, v_x);",
        &["smoothstep(c, p, a)"],
    );
    fixes_clear(rule, "mediump", "", "  r = smoothstep(u_a, u_b, v_x);");
    fixes_clear(rule, "highp", "", "  r = smoothstep(u_a, u_b, v_x);");
}

#[test]
fn smoothstep_with_equal_constant_edges() {
    let rule = "smoothstep-edges";
    reports(
        rule,
        "highp",
        "",
        "  r = smoothstep(0.5, 0.5, v_x);",
        &["smoothstep(0.5, 0.5, v_x)"],
    );
    // Reversed constant edges are the quieter rule's.
    clean(rule, "highp", "", "  r = smoothstep(1.0, 0.0, v_x);");
    notes(
        "smoothstep-reversed-constant",
        "highp",
        "",
        "  r = smoothstep(1.0, 0.0, v_x);",
        &["smoothstep(1.0, 0.0, v_x)"],
    );
    // A vector reversed in some components and equal in none: a per-channel mirror.
    let mixed = "  r = smoothstep(vec3(3.0, 0.0, 3.0), vec3(2.0, 2.0, 4.0), vec3(v_x)).x;";
    clean(rule, "highp", "", mixed);
    notes(
        "smoothstep-reversed-constant",
        "highp",
        "",
        mixed,
        &["smoothstep(vec3(3.0, 0.0, 3.0), vec3(2.0, 2.0, 4.0), vec3(v_x))"],
    );
    // Equal in one component: that component divides by zero.
    reports(
        rule,
        "highp",
        "",
        "  r = smoothstep(vec2(1.0, 2.0), vec2(1.0, 3.0), vec2(v_x)).y;",
        &["smoothstep(vec2(1.0, 2.0), vec2(1.0, 3.0), vec2(v_x))"],
    );
}

#[test]
fn smoothstep_with_ordered_edges_is_fine() {
    let rule = "smoothstep-edges";
    clean(
        rule,
        "highp",
        "",
        "  r = smoothstep(0.0, 1.0, v_x) + smoothstep(u_a, u_a + 0.1, v_x);",
    );
    clean(
        rule,
        "mediump",
        "",
        "  r = smoothstep(u_a, max(u_b, u_a + 1e-3), v_x);",
    );
    clean(
        rule,
        "highp",
        "",
        "  float w = 0.01;\n  r = smoothstep(u_a - w, u_a + w, v_x);",
    );
}

#[test]
fn smoothstep_with_per_pixel_edges() {
    let rule = "smoothstep-edges";
    // Two inputs set independently can be equal.
    reports(
        rule,
        "highp",
        "",
        "  r = smoothstep(v_x, v_pos.x, 0.5);",
        &["smoothstep(v_x, v_pos.x, 0.5)"],
    );
    // Clamps of a dot product: ordered, but equal wherever both saturate (`d <= 0`).
    reports(
        rule,
        "highp",
        "",
        "  float d = dot(normalize(v_n), normalize(u_dir));\n  r = smoothstep(clamp(d - 0.3, 0.0, 1.0), clamp(d, 0.0, 1.0), v_x);",
        &["smoothstep(clamp(d - 0.3, 0.0, 1.0), clamp(d, 0.0, 1.0), v_x)"],
    );
    // The antialiasing idiom: a width from a derivative, either order.
    clean(
        rule,
        "highp",
        "",
        "  float w = fwidth(v_x);\n  r = smoothstep(0.5 - w, 0.5 + w, v_x) + smoothstep(0.5 + w, 0.5 - w, v_x);",
    );
    // A constant gap below the spacing of floats at the edges' magnitude.
    reports(
        rule,
        "highp",
        "",
        "  r = smoothstep(u_a, u_a + 1e-9, v_x);",
        &["smoothstep(u_a, u_a + 1e-9, v_x)"],
    );
}

// ----- division-by-difference -----

#[test]
fn division_by_a_difference_of_uniforms() {
    let rule = "division-by-difference";
    reports(
        rule,
        "highp",
        "",
        "  r = clamp((v_x - u_b) / (u_a - u_b), 0.0, 1.0);",
        &["(u_a - u_b)"],
    );
    reports(
        rule,
        "highp",
        "",
        "  float range = u_a - u_b;\n  r = clamp((v_x - u_b) / range, 0.0, 1.0);",
        &["range"],
    );
    reports(
        rule,
        "highp",
        "struct Light { float cutOff; float outerCutOff; }; uniform Light light;",
        "  float epsilon = light.cutOff - light.outerCutOff;\n  r = (v_x - light.outerCutOff) / epsilon;",
        &["epsilon"],
    );
    fixes_clear(
        rule,
        "highp",
        "",
        "  float range = u_a - u_b;\n  r = clamp((v_x - u_b) / range, 0.0, 1.0);",
    );
}

#[test]
fn a_guarded_or_non_uniform_divisor_is_fine() {
    let rule = "division-by-difference";
    clean(
        rule,
        "highp",
        "",
        "  r = (v_x - u_b) / max(u_a - u_b, 1e-4);",
    );
    clean(rule, "highp", "", "  r = v_x / (u_a + 1.0 - u_a);");
    clean(
        rule,
        "highp",
        "",
        "  r = v_x / (v_pos.x - v_pos.y) + v_x / u_a + v_x / (abs(u_a - u_b) + 0.001);",
    );
}

#[test]
fn division_by_a_shading_term_zero_on_the_unlit_side() {
    let rule = "division-by-difference";
    let cosines = "  vec3 n = normalize(v_n);\n  float nl = max(dot(n, normalize(v_h)), 0.0);\n  \
                   float nv = clamp(dot(n, normalize(-v_pos)), 0.0, 1.0);\n";
    // Cook–Torrance's denominator, Neubelt's sheen visibility, Smith–GGX's sum.
    reports(
        rule,
        "highp",
        "",
        &format!("{cosines}  r = v_x / (4.0 * nl * nv);"),
        &["(4.0 * nl * nv)"],
    );
    reports(
        rule,
        "highp",
        "",
        &format!("{cosines}  r = 1.0 / (4.0 * (nl + nv - nl * nv));"),
        &["(4.0 * (nl + nv - nl * nv))"],
    );
    reports(
        rule,
        "highp",
        "",
        &format!("{cosines}  float gv = nl * sqrt(nv * nv + u_a);\n  float gl = nv * sqrt(nl * nl + u_a);\n  r = 0.5 / (gv + gl);"),
        &["(gv + gl)"],
    );
    // A parameter named for the clamped cosine, passed an input as such (lygia's harness).
    reports(
        rule,
        "highp",
        "float vis(float NoV, float NoL) { return 0.5 / mix(2.0 * NoL * NoV, NoL + NoV, u_a); }",
        "  r = vis(v_x, v_pos.x);",
        &["mix(2.0 * NoL * NoV, NoL + NoV, u_a)"],
    );
    fixes_clear(
        rule,
        "highp",
        "",
        &format!("{cosines}  r = v_x / (4.0 * nl * nv);"),
    );
}

#[test]
fn a_shading_term_kept_from_zero_is_fine() {
    let rule = "division-by-difference";
    let cosines = "  vec3 n = normalize(v_n);\n  float nl = max(dot(n, normalize(v_h)), 0.0);\n  \
                   float nv = clamp(dot(n, normalize(-v_pos)), 0.0, 1.0);\n";
    // Guarded, floored, tested, a raw cosine (0 on a line of pixels), a sum with a constant.
    clean(
        rule,
        "highp",
        "",
        &format!(
            "{cosines}  r = v_x / (4.0 * nl * nv + 0.0001) + v_x / max(nl, 1e-4) + v_x / (nl + 0.5)\n    \
             + v_x / dot(n, normalize(v_h));\n  if (nl > 0.0 && nv > 0.0) {{ r += 1.0 / (nl * nv); }}"
        ),
    );
    // One call of a helper with a clamped cosine says nothing of another call's argument: GGX's
    // `a2 / pow2(pow2(NdotH) * (a2 - 1.0) + 1.0)`.
    clean(
        rule,
        "highp",
        "float pow2(float x) { return x * x; }",
        &format!("{cosines}  r = u_a / pow2(pow2(nl) * (u_a - 1.0) + 1.0);"),
    );
    // A parameter with another name, or a cosine-named one passed a computed value.
    clean(
        rule,
        "highp",
        "float f(float k, float NoL) { return 1.0 / k + 1.0 / NoL; }",
        "  r = f(v_x, 0.5 + v_x * v_x);",
    );
}

// ----- normalize-zero -----

#[test]
fn normalize_of_a_cross_product_or_per_draw_difference() {
    let rule = "normalize-zero";
    reports(
        rule,
        "highp",
        "",
        "  r = normalize(cross(u_up, u_dir)).x;",
        &["cross(u_up, u_dir)"],
    );
    reports(
        rule,
        "highp",
        "",
        "  r = normalize(cross(normalize(v_n), vec3(0.0, 1.0, 0.0))).x;",
        &["cross(normalize(v_n), vec3(0.0, 1.0, 0.0))"],
    );
    reports(
        rule,
        "highp",
        "",
        "  vec3 f = u_target - u_eye;\n  r = normalize(f).x;",
        &["f"],
    );
}

#[test]
fn normalize_of_inputs_transforms_and_per_pixel_vectors_is_fine() {
    let rule = "normalize-zero";
    clean(
        rule,
        "highp",
        "",
        "  r = normalize(v_n).x + normalize(u_dir).x + normalize(-u_dir).x;",
    );
    clean(
        rule,
        "highp",
        "",
        "  r = normalize(u_eye - v_pos).x + normalize(normalize(v_n) + normalize(v_h)).x;",
    );
    clean(rule, "highp", "", "  r = normalize(cross(v_n, v_t)).x;");
    clean(
        rule,
        "highp",
        "",
        "  r = normalize(vec3(u_m * vec4(u_dir, 0.0))).x;",
    );
    clean(
        rule,
        "highp",
        "",
        "  r = normalize(cross(vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0))).x;",
    );
    // A camera frame: the second and third cross products are of perpendicular vectors.
    reports(
        rule,
        "highp",
        "",
        "  vec3 f = normalize(u_dir);\n  vec3 right = normalize(cross(f, vec3(0.0, 1.0, 0.0)));\n  vec3 up = normalize(cross(right, f));\n  right = normalize(cross(up, f));\n  r = right.x + up.y;",
        &["cross(f, vec3(0.0, 1.0, 0.0))"],
    );
}

// ----- mediump-overflow -----

#[test]
fn mediump_overflow() {
    let rule = "mediump-overflow";
    reports(
        rule,
        "mediump",
        "",
        "  r = pow(u_a, 150.0);",
        &["pow(u_a, 150.0)"],
    );
    reports(
        rule,
        "mediump",
        "",
        "  float x = u_a * 1000.0;\n  r = x * x;",
        &["x * x"],
    );
    reports(
        rule,
        "mediump",
        "",
        "  r = exp(u_a * 2.0);",
        &["exp(u_a * 2.0)"],
    );
    reports(
        rule,
        "mediump",
        "",
        "  r = length(v_pos * 100.0);",
        &["length(v_pos * 100.0)"],
    );
    // A guard below mediump's smallest normal number flushes to zero.
    reports(
        rule,
        "mediump",
        "",
        "  r = v_x / max(u_a - u_b, 1e-6);",
        &["max(u_a - u_b, 1e-6)"],
    );
    // 60000 fits; scaled by more than 1 it does not.
    reports(
        rule,
        "mediump",
        "",
        "  float x = u_a * 6000.0;\n  r = x * 1.5;",
        &["x * 1.5"],
    );
    // Likewise through a parameter that its one call sets to 1.5.
    reports(
        rule,
        "mediump",
        "float scale(float x, float k) { return x * k; }",
        "  r = scale(u_a * 6000.0, 1.5);",
        &["x * k"],
    );
}

#[test]
fn mediump_without_overflow_and_highp_are_fine() {
    let rule = "mediump-overflow";
    clean(rule, "highp", "", "  float x = u_a * 1000.0;\n  r = pow(u_a, 150.0) + x * x + exp(u_a * 2.0) + v_x / max(u_a, 1e-6);");
    clean(
        rule,
        "mediump",
        "",
        "  r = pow(max(dot(normalize(v_n), normalize(v_h)), 0.0), 150.0);",
    );
    clean(
        rule,
        "mediump",
        "",
        "  r = clamp((v_x - u_b) / max(u_a - u_b, 1e-4), 0.0, 1.0);",
    );
    clean(rule, "mediump", "", "  r = u_a * u_b * u_k * v_x;");
    // A constant of magnitude at most 1 only shrinks what it scales, also as a parameter
    // that every call sets to one.
    clean(
        rule,
        "mediump",
        "",
        "  float x = u_a * 6000.0;\n  r = x * 0.9 + x * -1.0 + 1.0 * x;",
    );
    clean(
        rule,
        "mediump",
        "float scale(float x, float k) { return x * k; }",
        "  r = scale(u_a * 6000.0, 0.9) + scale(u_a * 6000.0, -1.0);",
    );
    clean(
        rule,
        "mediump",
        "",
        "  r = normalize(v_pos).x + length(v_pos) + exp(-u_a * v_x);",
    );
    // A highp variable in a mediump shader.
    clean(
        rule,
        "mediump",
        "",
        "  highp float x = u_a * 1000.0;\n  highp float y = x * x;\n  r = y > 1.0 ? 1.0 : 0.0;",
    );
}

// ----- guards -----

#[test]
fn guarded_code_is_not_reported() {
    let d = "  float d = dot(normalize(v_n), normalize(v_h));\n";
    clean(
        "pow-negative-base",
        "highp",
        "",
        &format!("{d}  if (d > 0.0) {{ r = pow(d, u_k); }}"),
    );
    clean(
        "pow-negative-base",
        "highp",
        "",
        &format!("{d}  r = d > 0.0 ? pow(d, u_k) : 0.0;"),
    );
    clean(
        "pow-negative-base",
        "highp",
        "",
        &format!("{d}  if (d <= 0.0) {{ discard; }}\n  r = pow(d, u_k);"),
    );
    clean(
        "pow-negative-base",
        "highp",
        "",
        "  if (dot(v_n, v_h) > 0.0) { r = pow(dot(v_n, v_h), u_k); }",
    );
    reports(
        "pow-negative-base",
        "highp",
        "",
        &format!("{d}  if (d > -0.5) {{ r = pow(d, u_k); }}"),
        &["d"],
    );
    clean(
        "pow-zero-base",
        "highp",
        "",
        &format!("{d}  if (d > 0.0) {{ r = pow(d, u_k - 1.0); }}"),
    );
    clean(
        "acos-domain",
        "highp",
        "",
        &format!("{d}  if (abs(d) <= 1.0) {{ r = acos(d); }}"),
    );
    clean(
        "division-by-difference",
        "highp",
        "",
        "  if (u_a != u_b) { r = v_x / (u_a - u_b); }",
    );
    clean(
        "division-by-difference",
        "highp",
        "",
        "  if (u_a > u_b) { r = v_x / (u_a - u_b); }",
    );
    clean(
        "division-by-difference",
        "highp",
        "",
        "  float e = u_a - u_b;\n  if (abs(e) > 1e-4) { r = v_x / e; }",
    );
    clean(
        "smoothstep-edges",
        "highp",
        "",
        "  if (u_a < u_b) { r = smoothstep(u_a, u_b, v_x); }",
    );
    clean(
        "smoothstep-edges",
        "highp",
        "",
        "  r = u_a < u_b ? smoothstep(u_a, u_b, v_x) : step(u_a, v_x);",
    );
    clean(
        "normalize-zero",
        "highp",
        "",
        "  vec3 c = cross(u_up, u_dir);\n  r = (dot(c, c) > 1e-12 ? normalize(c) : u_dir).x;",
    );
    clean(
        "normalize-zero",
        "highp",
        "",
        "  vec3 c = cross(u_up, u_dir);\n  if (length(c) > 0.0) { r = normalize(c).x; }",
    );
}

// ----- options and suppressions -----

const HAZARD: &str = "  r = pow(dot(normalize(v_n), normalize(v_h)), u_k);";

#[test]
fn findings_are_warnings_unless_denied() {
    let s = compiled(&frag("highp", "", HAZARD));
    let d = lint(&s, &LintOptions::default());
    assert_eq!(d.len(), 1);
    assert_eq!(d[0].severity, Severity::Warning);
    assert!(d[0].fix.is_some() && d[0].help.is_some() && !d[0].label.is_empty());
    let denied = lint(&s, &LintOptions::new().deny("pow-negative-base"));
    assert_eq!(denied[0].severity, Severity::Error);
    assert!(lint(&s, &LintOptions::new().allow("pow-negative-base")).is_empty());
    assert!(lint(&s, &LintOptions::new().allow("all")).is_empty());
    assert_eq!(
        lint(
            &s,
            &LintOptions::new().allow("all").warn("pow-negative-base")
        )
        .len(),
        1
    );
    assert_eq!(
        lint(&s, &LintOptions::new().deny("all"))[0].severity,
        Severity::Error
    );
}

#[test]
fn notes_are_off_by_default_and_levels_move_them() {
    let reversed = "  r = smoothstep(1.0, 0.0, v_x);";
    let one_uniform = "  r = v_x / (u_a - 1.0);";
    let s = compiled(&frag("highp", "", reversed));
    assert!(lint(&s, &LintOptions::default()).is_empty());
    let notes = lint(&s, &LintOptions::default().notes(true));
    assert_eq!(notes.len(), 1);
    assert_eq!(notes[0].severity, Severity::Note);
    // `--warn RULE` makes a quiet rule's findings warnings.
    let warned = lint(
        &s,
        &LintOptions::default().warn("smoothstep-reversed-constant"),
    );
    assert_eq!(warned[0].severity, Severity::Warning);
    // A note a rule grades as such stays a note under `--deny`, and names the uniform.
    let s = compiled(&frag("highp", "", one_uniform));
    let denied = lint(&s, &LintOptions::default().deny("all").notes(true));
    assert_eq!(denied.len(), 1);
    assert_eq!(denied[0].severity, Severity::Note);
    assert!(denied[0].message.contains("`u_a`"), "{}", denied[0].message);
    assert!(lint(&s, &LintOptions::default().deny("all")).is_empty());
    // `--note RULE` makes every finding of a rule a note.
    let s = compiled(&frag("highp", "", HAZARD));
    let quiet = lint(
        &s,
        &LintOptions::default().note("pow-negative-base").notes(true),
    );
    assert_eq!(quiet[0].severity, Severity::Note);
    assert!(lint(&s, &LintOptions::default().note("pow-negative-base")).is_empty());
}

#[test]
fn unknown_rules_are_rejected_by_set() {
    let mut o = LintOptions::new();
    assert!(o.set("pow-negative-base", Level::Deny).is_ok());
    assert!(o.set("all", Level::Allow).is_ok());
    let e = o.set("pow-negativ-base", Level::Deny).unwrap_err();
    assert!(e.to_string().contains("pow-negativ-base"));
}

#[test]
fn essl_allow_comments_silence_a_rule_on_their_line_and_the_next() {
    let same_line =
        "  r = pow(dot(normalize(v_n), normalize(v_h)), u_k); // essl-allow: pow-negative-base";
    assert!(findings(&frag("highp", "", same_line)).is_empty());
    let codes = |body: &str| -> Vec<&'static str> {
        findings(&frag("highp", "", body))
            .iter()
            .map(|d| d.0)
            .collect()
    };
    // `acos-domain` silences nothing here: it is reported as unused.
    let line_before = "  // essl-allow: pow-negative-base, acos-domain\n  r = pow(dot(normalize(v_n), normalize(v_h)), u_k);";
    assert_eq!(codes(line_before), ["unused-essl-allow"]);
    let other_rule =
        "  // essl-allow: acos-domain\n  r = pow(dot(normalize(v_n), normalize(v_h)), u_k);";
    assert_eq!(
        codes(other_rule),
        ["unused-essl-allow", "pow-negative-base"]
    );
    let too_far = "  // essl-allow: pow-negative-base\n\n  r = pow(dot(normalize(v_n), normalize(v_h)), u_k);";
    assert_eq!(codes(too_far), ["unused-essl-allow", "pow-negative-base"]);
}

#[test]
fn file_level_allows_and_unused_allows() {
    let body = "  r = pow(dot(normalize(v_n), normalize(v_h)), u_k);";
    let whole = format!(
        "{}// essl-allow-file: pow-negative-base\n",
        frag("highp", "", body)
    );
    assert!(findings(&whole).is_empty());
    let unused = findings(&frag(
        "highp",
        "",
        "  // essl-allow: acos-domain\n  r = 1.0;",
    ));
    assert_eq!(unused, [("unused-essl-allow", "acos-domain".to_string())]);
    // A rule that is not run is not reported as unused, and the check itself can be allowed.
    let s = compiled(&frag(
        "highp",
        "",
        "  // essl-allow: acos-domain\n  r = 1.0;",
    ));
    assert!(lint(&s, &LintOptions::default().allow("acos-domain")).is_empty());
    assert!(lint(&s, &LintOptions::default().allow("unused-essl-allow")).is_empty());
}

#[test]
fn a_shader_that_does_not_compile_has_no_findings() {
    let s = compile(
        SourceFile::new("t.frag", "#version 300 es\nvoid main() { x = 1; }\n"),
        Stage::Fragment,
        &CompileOptions::default(),
    );
    assert!(lint(&s, &LintOptions::default()).is_empty());
}

#[test]
fn every_rule_is_registered_once_with_a_page() {
    let mut ids: Vec<&str> = essl_lint::RULES.iter().map(|r| r.id).collect();
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids.len(), essl_lint::RULES.len());
    for r in essl_lint::RULES {
        assert!(essl_lint::rule(r.id).is_some());
        let quiet = matches!(r.id, "smoothstep-reversed-constant" | "mediump-time");
        assert_eq!(
            r.default_level,
            if quiet { Level::Note } else { Level::Warn }
        );
        let page = r.page();
        for section in [
            "## What it does",
            "## Why is this bad?",
            "## Example",
            "## Use instead",
            "## What it does not flag",
            "## References",
        ] {
            assert!(page.contains(section), "{}: no {section}", r.id);
        }
    }
}
