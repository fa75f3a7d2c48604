//! Every rule page's *Example* is a hazard the rule reports, and its *Use instead* is quiet: the
//! two `glsl` blocks are taken from the page ([`essl_lint::Rule::doc`]) and compiled in a
//! fragment shader whose declarations (what a block names but does not declare) are below.

use essl_lint::{lint, LintOptions, RULES};

/// What a rule's blocks need: the declarations outside `main`, the statements before both
/// blocks, the statements of the *Example* that the *Use instead* block uses without declaring
/// them, and the value the shader writes out (so that nothing is dead code).
struct Setting {
    rule: &'static str,
    globals: &'static str,
    before: &'static str,
    instead_needs: &'static str,
    sink: &'static str,
}

const DOT_FROM_DIRECTION: &str = "in vec3 v_surfaceToLight;\nuniform vec3 u_lightDirection;\n\
     uniform float u_innerLimit;\nuniform float u_outerLimit;";
const FROM_DIRECTION: &str =
    "float dotFromDirection = dot(normalize(v_surfaceToLight), -u_lightDirection);";

const SETTINGS: &[Setting] = &[
    Setting {
        rule: "acos-domain",
        globals: "struct Light { vec3 direction; };\nuniform Light light;\n\
                  struct SpotLightEx { vec3 up; };\nuniform SpotLightEx spotLightEx;",
        before: "",
        instead_needs: "float upCos = dot(light.direction, spotLightEx.up);",
        sink: "upAngle",
    },
    Setting {
        rule: "asin-domain",
        globals: "in vec3 v_position;",
        before: "vec3 p = v_position;",
        instead_needs: "",
        sink: "lat",
    },
    Setting {
        rule: "clamp-bounds",
        globals: "",
        before: "",
        instead_needs: "",
        sink: "isFrontFace",
    },
    Setting {
        rule: "division-by-difference",
        globals: DOT_FROM_DIRECTION,
        before: FROM_DIRECTION,
        instead_needs: "",
        sink: "inLight",
    },
    Setting {
        rule: "domain-atan2",
        globals: "uniform sampler2D u_normalMap;\nin vec2 v_uv;",
        before: "",
        instead_needs: "vec3 n = texture(u_normalMap, v_uv).xyz * 2.0 - 1.0;",
        sink: "phi",
    },
    Setting {
        rule: "domain-integer-division",
        globals: "in vec2 v_uv;\nflat in int v_index;",
        before: "int index = v_index;",
        instead_needs: "int bands = int(v_uv.x * 4.0);",
        sink: "float(cell)",
    },
    Setting {
        rule: "domain-inversesqrt",
        globals: "in vec3 v_normal;\nin vec3 v_surfaceToLight;",
        before: "vec3 n = normalize(v_normal);\nvec3 l = normalize(v_surfaceToLight);",
        instead_needs: "",
        sink: "k",
    },
    Setting {
        rule: "domain-log",
        globals: "uniform sampler2D u_hdr;\nin vec2 v_uv;",
        before: "",
        instead_needs: "",
        sink: "logLum",
    },
    Setting {
        rule: "domain-sqrt",
        globals: "in vec3 v_normal;\nin vec3 v_surfaceToView;",
        before: "float NdotV = dot(normalize(v_normal), normalize(v_surfaceToView));",
        instead_needs: "",
        sink: "sinTheta",
    },
    Setting {
        rule: "mediump-overflow",
        globals: "precision mediump float;",
        before: "",
        instead_needs: "",
        sink: "falloff",
    },
    Setting {
        rule: "mediump-time",
        globals: "precision mediump float;\nin vec2 uv;",
        before: "",
        instead_needs: "",
        sink: "wave",
    },
    Setting {
        rule: "non-uniform-derivative",
        globals: "uniform sampler2D u_detail;\nin vec2 v_uv;",
        before: "vec4 color = vec4(0.0);",
        instead_needs: "",
        sink: "color.x",
    },
    Setting {
        rule: "normalize-zero",
        globals: "struct SpotLightEx { vec3 up; };\nuniform SpotLightEx spotLightEx;\n\
                  struct SpotLight { vec3 direction; };\nuniform SpotLight spotLight;",
        before: "",
        instead_needs: "",
        sink: "left.x",
    },
    Setting {
        rule: "pow-negative-base",
        globals: "in vec3 v_normal;\nin vec3 v_halfVector;\nuniform float u_shininess;",
        before: "vec3 normal = normalize(v_normal);\nvec3 halfVector = normalize(v_halfVector);",
        instead_needs: "",
        sink: "specular",
    },
    Setting {
        rule: "pow-zero-base",
        globals: "in vec3 v_normal;\nin vec3 v_surfaceToLight;\nuniform float u_k;",
        before: "vec3 n = normalize(v_normal);\nvec3 l = normalize(v_surfaceToLight);\n\
                 float k = u_k;",
        instead_needs: "",
        sink: "f",
    },
    Setting {
        rule: "smoothstep-edges",
        globals: DOT_FROM_DIRECTION,
        before: FROM_DIRECTION,
        instead_needs: "",
        sink: "inLight",
    },
    Setting {
        rule: "smoothstep-reversed-constant",
        globals: "in vec2 v_uv;",
        before: "vec2 d = v_uv - 0.5;",
        instead_needs: "",
        sink: "a",
    },
    Setting {
        rule: "texel-fetch-range",
        globals: "uniform sampler2D u_image;",
        before: "",
        instead_needs: "",
        sink: "left.x",
    },
    Setting {
        rule: "uninitialised-read",
        globals: "precision highp sampler2DShadow;\nuniform sampler2DShadow u_shadowMap;\n\
                  in vec4 v_shadowCoord;",
        before: "vec4 coord = v_shadowCoord / v_shadowCoord.w;\n\
                 bool inFrustum = all(greaterThanEqual(coord.xyz, vec3(0.0))) && \
                 all(lessThanEqual(coord.xyz, vec3(1.0)));\nvec3 color = vec3(1.0);",
        instead_needs: "",
        sink: "color.x",
    },
    Setting {
        rule: "unused-essl-allow",
        globals: "in float v_d;",
        before: "float d = v_d;",
        instead_needs: "",
        sink: "f",
    },
];

/// The first ```` ```glsl ```` block after the heading `## {heading}` of a page.
fn block<'a>(page: &'a str, heading: &str) -> &'a str {
    let after = page
        .split_once(&format!("\n## {heading}\n"))
        .unwrap_or_else(|| panic!("a `## {heading}` section in:\n{page}"))
        .1;
    let code = after
        .split_once("```glsl\n")
        .unwrap_or_else(|| panic!("a glsl block after `## {heading}`"))
        .1;
    code.split_once("```").expect("a closed block").0
}

/// A fragment shader holding `code`: its declarations (`precision`, `uniform`, `in`, `struct`
/// lines) outside `main` with the setting's, its statements in `main` after `before`; `…`
/// lines (the page's elision) dropped.
fn shader(s: &Setting, before: &str, code: &str) -> String {
    let global = |l: &str| {
        let l = l.trim_start();
        ["precision ", "uniform ", "in ", "struct ", "flat in "]
            .iter()
            .any(|p| l.starts_with(p))
    };
    let mut globals: Vec<&str> = s.globals.lines().collect();
    for l in code.lines().filter(|l| global(l)) {
        if !globals.contains(&l) {
            globals.push(l);
        }
    }
    let body: Vec<&str> = code
        .lines()
        .filter(|l| !global(l) && l.trim() != "…")
        .collect();
    let float = if globals
        .iter()
        .any(|l| l.starts_with("precision ") && l.ends_with(" float;"))
    {
        ""
    } else {
        "precision highp float;\n"
    };
    format!(
        "#version 300 es\n{float}{}\nout vec4 essl_out;\nvoid main() {{\n{before}\n{}\n    essl_out = vec4({});\n}}\n",
        globals.join("\n"),
        body.join("\n"),
        s.sink
    )
}

/// The findings of `rule` in `text`, notes included (severity and line), after checking that
/// the shader compiles.
fn findings(rule: &str, text: &str) -> Vec<String> {
    let s = super::compiled(&format!("{rule}.frag"), text);
    lint(&s, &LintOptions::default().notes(true))
        .into_iter()
        .filter(|d| d.code == rule)
        .map(|d| {
            format!(
                "{:?} at line {}",
                d.severity,
                s.file.line_col(d.span.start).line
            )
        })
        .collect()
}

#[test]
fn every_rule_has_a_setting() {
    for r in RULES {
        assert!(
            SETTINGS.iter().any(|s| s.rule == r.id),
            "{}: no setting for its page's examples",
            r.id
        );
    }
}

#[test]
fn each_page_example_is_reported_and_its_fix_is_quiet() {
    let mut wrong = Vec::new();
    for s in SETTINGS {
        let rule = RULES
            .iter()
            .find(|r| r.id == s.rule)
            .unwrap_or_else(|| panic!("a rule {}", s.rule));
        let example = shader(s, s.before, block(rule.doc, "Example"));
        if findings(s.rule, &example).is_empty() {
            wrong.push(format!(
                "{}: the Example is not reported:\n{example}",
                s.rule
            ));
        }
        let before_instead = format!("{}\n{}", s.before, s.instead_needs);
        let instead = shader(s, &before_instead, block(rule.doc, "Use instead"));
        let found = findings(s.rule, &instead);
        if !found.is_empty() {
            wrong.push(format!(
                "{}: Use instead is reported ({found:?}):\n{instead}",
                s.rule
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n\n"));
}
