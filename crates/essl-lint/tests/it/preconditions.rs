//! The uniform preconditions (`essl_lint::preconditions`): what each rule exports for the
//! runtime check, what it must not export (guarded or self-ordered code, values that depend on
//! inputs), the names of struct members, array elements and helper parameters, and the
//! evaluation of the conditions.

use essl::source::SourceFile;
use essl::{compile, CompileOptions, Shader, Stage};
use essl_lint::precondition::{Condition, Outcome, Precision, UniformRef, Value};
use essl_lint::{preconditions, Precondition};

/// A fragment shader with the usual declarations around `body` (statements of `main`).
fn frag(precision: &str, decls: &str, body: &str) -> String {
    format!(
        "#version 300 es\nprecision {precision} float;\n\
         uniform float u_a; uniform float u_b; uniform float u_k; uniform vec3 u_up; uniform vec3 u_dir;\n\
         uniform vec3 u_eye; uniform vec3 u_target; uniform vec2 u_size;\n\
         in vec3 v_n; in vec3 v_h; in float v_x;\n\
         out vec4 o;\n{decls}\nvoid main() {{\n  float r = 0.0;\n{body}\n  o = vec4(r);\n}}\n"
    )
}

fn compiled(text: &str) -> Shader {
    super::compiled("t.frag", text)
}

/// (rule, condition, text of the span) of every precondition but the `non-finite-uniform`
/// ones.
fn found(text: &str) -> Vec<(&'static str, String, String)> {
    let s = compiled(text);
    preconditions(&s)
        .iter()
        .filter(|p| p.rule != "non-finite-uniform")
        .map(|p| {
            (
                p.rule,
                p.condition.to_string(),
                s.file.slice(p.span).to_string(),
            )
        })
        .collect()
}

fn one(text: &str) -> (&'static str, String, String) {
    let f = found(text);
    assert_eq!(f.len(), 1, "{f:#?}");
    f.into_iter().next().expect("one")
}

fn values<'a>(vals: &'a [(&'a str, &'a [f64])]) -> impl FnMut(&UniformRef) -> Option<Value> + 'a {
    move |r: &UniformRef| {
        vals.iter()
            .find(|(n, _)| *n == r.name(None))
            .map(|(_, v)| Value::new(v))
    }
}

fn violated(p: &Precondition, vals: &[(&str, &[f64])]) -> bool {
    matches!(p.check(&mut values(vals)), Outcome::Violated(_))
}

#[test]
fn smoothstep_edges_from_uniforms() {
    let t = frag("highp", "", "  r = smoothstep(u_a, u_b, v_x);");
    assert_eq!(
        one(&t),
        (
            "smoothstep-edges",
            "u_a < u_b".into(),
            "smoothstep(u_a, u_b, v_x)".into()
        )
    );
    let s = compiled(&t);
    let pre = preconditions(&s);
    let p = pre.iter().find(|p| p.rule == "smoothstep-edges").unwrap();
    assert!(p.reported, "the static rule reports it too");
    assert_eq!(p.precision, Precision::High);
    assert_eq!(p.stage, Stage::Fragment);
    assert_eq!(s.file.line_col(p.span.start).line, 10);
    assert!(!violated(p, &[("u_a", &[0.9]), ("u_b", &[0.95])]));
    assert!(violated(p, &[("u_a", &[0.9]), ("u_b", &[0.9])]));
    assert!(violated(p, &[("u_a", &[0.95]), ("u_b", &[0.9])]));
    assert!(violated(p, &[("u_a", &[f64::NAN]), ("u_b", &[0.9])]));
}

#[test]
fn smoothstep_ordered_by_the_shader_is_not_exported() {
    for body in [
        "  r = smoothstep(u_a, max(u_b, u_a + 1e-3), v_x);",
        "  r = smoothstep(u_a, u_a + 0.1, v_x);",
        "  if (u_a < u_b) { r = smoothstep(u_a, u_b, v_x); }",
        "  r = smoothstep(0.0, 1.0, v_x);",
        "  r = smoothstep(v_x, v_x + 1.0, u_a);",
    ] {
        let f = found(&frag("highp", "", body));
        assert!(
            !f.iter().any(|p| p.0 == "smoothstep-edges"),
            "{body}: {f:?}"
        );
    }
    // Edges from an input: not a uniform condition.
    let f = found(&frag("highp", "", "  r = smoothstep(v_x, u_a, 0.5);"));
    assert!(f.is_empty(), "{f:?}");
}

#[test]
fn division_by_a_difference_of_uniforms() {
    let t = frag(
        "mediump",
        "",
        "  float range = u_a - u_b;\n  r = clamp((v_x - u_b) / range, 0.0, 1.0);",
    );
    assert_eq!(
        one(&t),
        (
            "division-by-difference",
            "u_a != u_b".into(),
            "range".into()
        )
    );
    let s = compiled(&t);
    let pre = preconditions(&s);
    let p = &pre.iter().find(|p| p.rule != "non-finite-uniform").unwrap();
    assert_eq!(p.precision, Precision::Low);
    assert!(violated(p, &[("u_a", &[0.5]), ("u_b", &[0.5])]));
    assert!(!violated(p, &[("u_a", &[0.9]), ("u_b", &[0.8])]));
    // Distinct in 32 bits, the same 16-bit float.
    assert!(violated(p, &[("u_a", &[0.9]), ("u_b", &[0.9001])]));
    // Guarded: nothing.
    let f = found(&frag(
        "highp",
        "",
        "  r = (v_x - u_b) / max(u_a - u_b, 1e-4);",
    ));
    assert!(f.is_empty(), "{f:?}");
}

#[test]
fn division_by_a_uniform() {
    assert_eq!(
        one(&frag("highp", "", "  r = (gl_FragCoord.xy / u_size).x;")),
        ("division-by-zero", "u_size != 0".into(), "u_size".into())
    );
    let f = found(&frag("highp", "", "  r = v_x / (2.0 * acos(u_a));"));
    let d = f
        .iter()
        .find(|p| p.0 == "division-by-zero")
        .expect("a divisor");
    assert_eq!(d.1, "2 * acos(u_a) != 0");
    for body in [
        "  r = v_x / 2.0;",
        "  r = u_a / v_x;",
        "  r = v_x / (u_a * u_a + 1.0);",
        "  if (u_k != 0.0) { r = v_x / u_k; }",
    ] {
        let f = found(&frag("highp", "", body));
        assert!(
            !f.iter().any(|p| p.0.starts_with("division")),
            "{body}: {f:?}"
        );
    }
}

#[test]
fn normalize_of_uniform_vectors() {
    assert_eq!(
        one(&frag("highp", "", "  r = normalize(u_dir).x;")),
        ("normalize-zero", "length(u_dir) > 0".into(), "u_dir".into())
    );
    assert_eq!(
        one(&frag("highp", "", "  r = normalize(u_target - u_eye).x;")).1,
        "length(u_target - u_eye) > 0"
    );
    let t = frag("highp", "", "  r = normalize(cross(u_up, u_dir)).x;");
    assert_eq!(one(&t).1, "length(cross(u_up, u_dir)) > 0");
    let s = compiled(&t);
    let pre = preconditions(&s);
    let p = pre.iter().find(|p| p.rule == "normalize-zero").unwrap();
    assert!(matches!(p.condition, Condition::NotParallel(..)));
    assert!(violated(
        p,
        &[("u_up", &[0.0, 1.0, 0.0]), ("u_dir", &[0.0, -3.0, 0.0])]
    ));
    assert!(violated(
        p,
        &[("u_up", &[0.0, 1.0, 0.0]), ("u_dir", &[0.0, 0.0, 0.0])]
    ));
    assert!(!violated(
        p,
        &[("u_up", &[0.0, 1.0, 0.0]), ("u_dir", &[0.0, -1.0, 0.2])]
    ));
    for body in [
        "  r = normalize(v_n).x;",
        "  r = normalize(u_eye - v_n).x;",
        "  r = normalize(u_dir + vec3(0.0, 0.0, 1e6) * 0.0 + vec3(1.0)).x * 0.0;",
        "  vec3 c = cross(u_up, u_dir);\n  r = dot(c, c) > 1e-12 ? normalize(c).x : 0.0;",
    ] {
        let f = found(&frag("highp", "", body));
        assert!(
            !f.iter()
                .any(|p| p.0 == "normalize-zero" && !p.1.contains("vec3(1")),
            "{body}: {f:?}"
        );
    }
}

#[test]
fn pow_exponent_and_base() {
    assert_eq!(
        one(&frag(
            "highp",
            "",
            "  r = pow(max(dot(normalize(v_n), normalize(v_h)), 0.0), u_k);"
        )),
        (
            "pow-zero-base",
            "u_k > 0".into(),
            "pow(max(dot(normalize(v_n), normalize(v_h)), 0.0), u_k)".into()
        )
    );
    assert_eq!(
        one(&frag("highp", "", "  r = pow(u_a, 2.0);")),
        ("pow-negative-base", "u_a >= 0".into(), "u_a".into())
    );
    let f = found(&frag("highp", "", "  r = pow(u_a, u_k);"));
    let rules: Vec<_> = f.iter().map(|p| (p.0, p.1.as_str())).collect();
    assert_eq!(
        rules,
        [
            ("pow-zero-base", "u_a != 0 || u_k > 0"),
            ("pow-negative-base", "u_a >= 0")
        ]
    );
    for body in [
        "  r = pow(max(dot(v_n, v_h), 1e-4), u_k);",
        "  r = pow(max(v_x, 0.0), 2.0);",
        "  if (u_k > 0.0) { r = pow(max(v_x, 0.0), u_k); }",
        "  r = pow(max(v_x, 0.0), v_x);",
    ] {
        let f = found(&frag("highp", "", body));
        assert!(!f.iter().any(|p| p.0.starts_with("pow")), "{body}: {f:?}");
    }
}

#[test]
fn acos_of_a_uniform() {
    assert_eq!(
        one(&frag("highp", "", "  r = acos(u_a);")),
        ("acos-domain", "-1 <= u_a <= 1".into(), "u_a".into())
    );
    assert_eq!(one(&frag("highp", "", "  r = asin(u_a);")).0, "asin-domain");
    assert!(found(&frag("highp", "", "  r = acos(clamp(u_a, -1.0, 1.0));")).is_empty());
}

#[test]
fn struct_members_and_array_elements_have_webgl_names() {
    let decls = "struct Light { vec3 direction; float cutOff; float outerCutOff; };\n\
                 uniform Light light;\nuniform Light lights[3];\nuniform float u_w[4];";
    let f = found(&frag(
        "highp",
        decls,
        "  float eps = light.cutOff - light.outerCutOff;\n  r = (v_x - light.outerCutOff) / eps;\n\
           r += normalize(-lights[1].direction).x;\n\
           for (int i = 0; i < 3; i++) { r += smoothstep(lights[i].outerCutOff, lights[i].cutOff, v_x); }\n\
           r += v_x / u_w[2];",
    ));
    let conds: Vec<&str> = f.iter().map(|p| p.1.as_str()).collect();
    assert_eq!(
        conds,
        [
            "light.cutOff != light.outerCutOff",
            "length(-lights[1].direction) > 0",
            "lights[*].outerCutOff < lights[*].cutOff",
            "u_w[2] != 0"
        ]
    );
}

#[test]
fn helper_parameters_follow_each_call() {
    let decls = "float edge(float lo, float hi, float x) { return smoothstep(lo, hi, x); }";
    let t = frag(
        "highp",
        decls,
        "  r = edge(u_a, u_b, v_x) + edge(u_k, u_a, v_x) + edge(0.0, 1.0, v_x);",
    );
    let s = compiled(&t);
    let pre: Vec<Precondition> = preconditions(&s)
        .into_iter()
        .filter(|p| p.rule == "smoothstep-edges")
        .collect();
    let conds: Vec<String> = pre.iter().map(|p| p.condition.to_string()).collect();
    assert_eq!(conds, ["u_a < u_b", "u_k < u_a"]);
    for p in &pre {
        assert_eq!(s.file.slice(p.span), "smoothstep(lo, hi, x)");
        assert_eq!(p.call_sites.len(), 1);
        assert!(s.file.slice(p.call_sites[0]).starts_with("edge(u_"));
    }
}

#[test]
fn every_uniform_read_must_be_finite() {
    let t = frag(
        "highp",
        "struct S { float a; vec3 b; };\nuniform S s;\nuniform mat4 u_m;",
        "  r = u_a + u_a + s.a + (u_m * vec4(1.0)).x;",
    );
    let s = compiled(&t);
    let fin: Vec<String> = preconditions(&s)
        .iter()
        .filter(|p| p.rule == "non-finite-uniform")
        .map(|p| p.condition.to_string())
        .collect();
    assert_eq!(fin, ["isfinite(u_a)", "isfinite(s.a)", "isfinite(u_m)"]);
    let pre = preconditions(&s);
    let p = pre.iter().find(|p| p.rule == "non-finite-uniform").unwrap();
    assert!(violated(p, &[("u_a", &[f64::INFINITY])]));
    assert!(!violated(p, &[("u_a", &[1.0])]));
}

#[test]
fn the_seeds() {
    let repo = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let list = |path: &str| -> Vec<String> {
        let p = repo.join(path);
        let text = std::fs::read_to_string(&p).expect("the seed");
        let s = compile(
            SourceFile::new(path, text),
            Stage::from_path(&p).expect("a stage"),
            &CompileOptions::default(),
        );
        preconditions(&s)
            .iter()
            .filter(|p| p.rule != "non-finite-uniform")
            .map(|p| {
                format!(
                    "{} {} {}",
                    s.file.line_col(p.span.start).line,
                    p.rule,
                    p.condition
                )
            })
            .collect()
    };
    assert_eq!(
        list("crates/essl-lint/tests/articles/spot-smooth-nbsp.fixed.frag"),
        [
            "46 smoothstep-edges u_outerLimit < u_innerLimit",
            "50 pow-zero-base u_shininess > 0"
        ]
    );
    assert_eq!(
        list("crates/essl-lint/tests/articles/spot-linear.frag"),
        [
            "29 division-by-difference u_innerLimit != u_outerLimit",
            "31 pow-zero-base u_shininess > 0"
        ]
    );
    // The fixed twins guard every hazard in the shader, `pow`'s exponent included
    // (`max(u_shininess, 1e-4)`): no uniform value is left to check at draw time.
    assert!(list("shaders-glsl/spot-smooth-nbsp.fixed.frag").is_empty());
    assert!(list("shaders-glsl/spot-linear.frag").is_empty());
    assert_eq!(
        list("shaders-glsl/spot-flashlight-cookie.frag"),
        [
            "59 pow-zero-base material.shininess > 0",
            "63 normalize-zero length(-light.direction) > 0",
            "65 division-by-difference light.cutOff != light.outerCutOff",
            "66 division-by-zero viewPort != 0"
        ]
    );
    assert_eq!(
        list("shaders-glsl/spot-projected-texture.frag"),
        [
            "55 smoothstep-edges spotLights[0].coneCos < spotLights[0].penumbraCos",
            "87 acos-domain -1 <= spotLights[0].coneCos <= 1",
            "98 division-by-zero 2 * acos(spotLights[0].coneCos) != 0",
            "101 normalize-zero length(cross(spotLightExs[0].up, spotLights[0].direction)) > 0",
            "109 division-by-zero 2 * acos(spotLights[0].coneCos) != 0"
        ]
    );
}
