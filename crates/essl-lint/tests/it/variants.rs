//! The lints on the configurations a shader's `#ifdef`s select (`essl_lint::variants`).

use essl::CompileOptions;
use essl_lint::variants::{self, Found};
use essl_lint::{lint, LintOptions};

/// A fragment shader with `body` in `main`, its uniforms and inputs declared.
fn frag(body: &str) -> String {
    format!(
        "#version 300 es\nprecision highp float;\n\
         uniform float u_fogStart; uniform float u_fogEnd; uniform sampler2D u_tex;\n\
         in vec2 v_uv; in float v_clip; in float v_depth;\nout vec4 o;\n\
         void main() {{\n  o = vec4(1.0);\n{body}\n}}\n"
    )
}

/// The findings of the variants: (rule, span text, macros, notes).
fn found(text: &str, max: usize) -> Vec<(&'static str, String, Vec<String>, Vec<String>)> {
    let shader = super::compiled("t.frag", text);
    let options = LintOptions::default().notes(true);
    let base = lint(&shader, &options);
    let compile = CompileOptions::default();
    let flags = variants::flags(text, &compile);
    variants::lint(&shader, &compile, &options, &base, &flags, max)
        .into_iter()
        .map(
            |Found {
                 diagnostic: d,
                 defines,
             }| {
                (
                    d.code,
                    shader.file.slice(d.span).to_string(),
                    defines,
                    d.notes,
                )
            },
        )
        .collect()
}

/// Asserts that one of a finding's notes says `text`.
fn assert_note(notes: &[String], text: &str) {
    assert!(notes.iter().any(|n| n.contains(text)), "{notes:?}");
}

#[test]
fn a_flag_s_code_is_linted_in_its_configuration() {
    let text = frag("#ifdef FOG\n  o *= (u_fogEnd - v_depth) / (u_fogEnd - u_fogStart);\n#endif");
    let shader = super::compiled("t.frag", &text);
    assert!(lint(&shader, &LintOptions::default().notes(true)).is_empty());
    let f = found(&text, variants::DEFAULT);
    assert_eq!(f.len(), 1, "{f:#?}");
    assert_eq!(f[0].0, "division-by-difference");
    assert_eq!(f[0].1, "(u_fogEnd - u_fogStart)");
    assert_eq!(f[0].2, ["FOG"]);
    assert_note(&f[0].3, "compiled only with `FOG` defined");
    assert!(found(&text, 0).is_empty(), "no configuration at 0");
}

#[test]
fn findings_of_the_configuration_checked_are_not_repeated() {
    let text = frag("  o *= 1.0 / (u_fogEnd - u_fogStart);\n#ifdef FOG\n  o.x += 1.0;\n#endif");
    let shader = super::compiled("t.frag", &text);
    assert_eq!(lint(&shader, &LintOptions::default()).len(), 1);
    assert!(found(&text, variants::DEFAULT).is_empty());
}

#[test]
fn a_configuration_that_does_not_compile_is_passed_over() {
    let text = frag("#ifdef NEEDS_A_HELPER\n  o *= helper(1.0 / (u_fogEnd - u_fogStart));\n#endif");
    assert!(found(&text, variants::DEFAULT).is_empty());
}

#[test]
fn flags_set_together_reach_what_each_alone_does_not() {
    // A clip plane's discard before a diffuse texture's lookup: each flag alone is clean.
    let text = frag(
        "#ifdef CLIPPLANE\n  if (v_clip > 0.0) discard;\n#endif\n\
         #ifdef DIFFUSE\n  o *= texture(u_tex, v_uv);\n#endif",
    );
    let f = found(&text, variants::DEFAULT);
    assert_eq!(f.len(), 1, "{f:#?}");
    assert_eq!(f[0].0, "non-uniform-derivative");
    assert_eq!(f[0].2, ["CLIPPLANE", "DIFFUSE"]);
    assert_note(&f[0].3, "every flag");
}

#[test]
fn a_nested_group_is_reached_with_its_outer_flag() {
    let text = frag(
        "#ifdef FOG\n#ifdef FOG_LINEAR\n  o *= 1.0 / (u_fogEnd - u_fogStart);\n#endif\n#endif",
    );
    let f = found(&text, 1);
    assert_eq!(
        f.len(),
        0,
        "the first configuration (FOG) alone does not reach it"
    );
    let f = found(&text, variants::DEFAULT);
    assert_eq!(f.len(), 1, "{f:#?}");
    assert_eq!(f[0].2, ["FOG", "FOG_LINEAR"]);
}

#[test]
fn a_flag_s_group_may_use_constants_the_host_defines_with_it() {
    // Cesium defines `SDF_EDGE` with `SDF`: the group compiles with it as 1.0.
    let text = frag(
        "#ifdef SDF\n  o *= (u_fogEnd - v_depth) / (u_fogEnd - u_fogStart) * SDF_EDGE;\n#endif",
    );
    let f = found(&text, variants::DEFAULT);
    assert_eq!(f.len(), 1, "{f:#?}");
    assert_eq!(f[0].2, ["SDF"]);
    assert_note(&f[0].3, "`SDF_EDGE`, which the text uses without defining");
    // Any other error leaves the configuration out.
    let text = frag(
        "#ifdef SDF\n  o *= (u_fogEnd - v_depth) / (u_fogEnd - u_fogStart) * sdfEdge;\n#endif",
    );
    assert!(found(&text, variants::DEFAULT).is_empty());
}

#[test]
fn a_count_the_includer_may_set_is_linted_at_1() {
    // lygia's `raymarchAO`: `RAYMARCH_AO_SAMPLES` defined as 1 divides by 0 in a constant.
    let text = frag(
        "#ifndef SAMPLES\n#define SAMPLES 5\n#endif\n  const float f = 1.0 / float(SAMPLES - 1);\n  \
         for (int i = 0; i < SAMPLES; i++) {\n    o.x += float(i) * f;\n  }",
    );
    let f = found(&text, variants::DEFAULT);
    assert_eq!(f.len(), 1, "{f:#?}");
    assert_eq!(f[0].0, "division-by-difference");
    assert_eq!(f[0].1, "1.0 / float(SAMPLES - 1)");
    assert_eq!(f[0].2, ["SAMPLES"]);
    assert_note(
        &f[0].3,
        "`SAMPLES` defined as 1, a count the text sets to 5",
    );
    // Not a loop's bound, already 1, or defined by the options: no configuration.
    for text in [
        frag("#ifndef SAMPLES\n#define SAMPLES 5\n#endif\n  o.x /= float(SAMPLES - 1);"),
        frag("#ifndef SAMPLES\n#define SAMPLES 1\n#endif\n  for (int i = 0; i < SAMPLES; i++) {\n    o.x /= float(SAMPLES);\n  }"),
    ] {
        assert!(found(&text, variants::DEFAULT).is_empty(), "{text}");
    }
}

#[test]
fn a_flag_s_group_divides_by_a_constant_0() {
    // lygia's stars: `m = float(ATMOSPHERE_STARS_LAYERS)` is 1 with the flag defined as 1.
    let text = frag(
        "#ifdef LAYERS\n  const float m = float(LAYERS);\n  \
         for (float i = 0.0; i < m; i++) {\n    o.x += i / (m - 1.0);\n  }\n#endif",
    );
    let f = found(&text, variants::DEFAULT);
    assert_eq!(f.len(), 1, "{f:#?}");
    assert_eq!(
        (f[0].0, f[0].1.as_str()),
        ("division-by-difference", "(m - 1.0)")
    );
    // With a constant the host defines, 1.0 for want of its value: nothing said.
    let text = frag("#ifdef SDF\n  o.x /= v_clip / (SDF_EDGE - 1.0);\n#endif");
    assert!(found(&text, variants::DEFAULT).is_empty());
}

#[test]
fn each_function_a_text_chooses_between_is_linted() {
    // lygia's `DIFFUSE_FNC`: `diffuseLambert` on WebGL, `diffuseOrenNayar` elsewhere.
    let text =
        "#version 300 es\n#define WEBGL\nprecision highp float;\nin float v_a; in float v_b;\n\
                out vec4 o;\nfloat lambert(float a, float b) { return max(a, 0.0); }\n\
                float oren(float a, float b) { return a / b; }\n\
                #ifndef DIFFUSE_FNC\n#ifdef WEBGL\n#define DIFFUSE_FNC lambert\n#else\n\
                #define DIFFUSE_FNC oren\n#endif\n#endif\n\
                void main() { o = vec4(DIFFUSE_FNC(v_a, v_b)); }\n";
    let f = found(text, variants::DEFAULT);
    assert_eq!(f.len(), 1, "{f:#?}");
    assert_eq!((f[0].0, f[0].1.as_str()), ("division-by-difference", "b"));
    assert_eq!(f[0].2, ["DIFFUSE_FNC"]);
    assert_note(&f[0].3, "`DIFFUSE_FNC` defined as `oren`");
    // One value only: no configuration.
    let single = text.replace("#define DIFFUSE_FNC oren", "#define DIFFUSE_FNC lambert");
    assert!(found(&single, variants::DEFAULT).is_empty(), "{single}");
}

#[test]
fn the_other_functions_of_a_choice_s_family_are_linted() {
    // lygia's `SPECULAR_FNC` defaults to `specularBlinnPhong` or `specularCookTorrance`; its
    // `specularGaussian` runs only where the includer defines the macro as it. A function of
    // the family with other arguments is a configuration that does not compile.
    let text = "#version 300 es\n#define WEBGL\nprecision highp float;\nin float v_a; in float v_b;\n\
                out vec4 o;\nfloat specularBlinnPhong(float a, float b) { return max(a, 0.0); }\n\
                float specularCookTorrance(float a, float b) { return max(b, 0.0); }\n\
                float specularGaussian(float a, float b) { return a / b; }\n\
                float specularHelper(vec3 a) { return 1.0 / a.x; }\n\
                #ifndef SPECULAR_FNC\n#ifdef WEBGL\n#define SPECULAR_FNC specularBlinnPhong\n#else\n\
                #define SPECULAR_FNC specularCookTorrance\n#endif\n#endif\n\
                void main() { o = vec4(SPECULAR_FNC(v_a, v_b)); }\n";
    let f = found(text, variants::DEFAULT);
    assert_eq!(f.len(), 1, "{f:#?}");
    assert_eq!((f[0].0, f[0].1.as_str()), ("division-by-difference", "b"));
    assert_note(&f[0].3, "`SPECULAR_FNC` defined as `specularGaussian`");
}

#[test]
fn a_level_the_conditionals_compare_is_linted_where_it_turns_every_group_on() {
    // Babylon's `NUM_BONE_INFLUENCERS`: the skinning under `> 0` and `> 1` runs for every mesh
    // with bones, and the baked vertex animation reads the bone attributes `> 0` declares.
    let text = "#version 300 es\n#ifndef BONES\n#define BONES 0\n#endif\nprecision highp float;\n\
                uniform vec4 u_vat; uniform float u_time; uniform float u_a; uniform float u_b;\n\
                #if BONES > 0\nin vec4 v_w;\n#endif\nout vec4 o;\nvoid main() {\n  o = vec4(1.0);\n\
                #if BONES > 1\n  o.x /= u_a - u_b;\n#endif\n\
                #ifdef VAT\n  float frames = u_vat.y - u_vat.x;\n  o.y = mod(u_time, frames) * v_w.x;\n#endif\n}\n";
    let f = found(text, variants::DEFAULT);
    let at = |s: &str| {
        f.iter()
            .find(|x| x.1 == s)
            .unwrap_or_else(|| panic!("{s}: {f:#?}"))
    };
    let (_, _, defines, notes) = at("u_a - u_b");
    assert_eq!(defines, &["BONES"]);
    assert_note(notes, "`BONES` defined as 2, a level the text sets to 0");
    let (_, _, defines, notes) = at("frames");
    assert_eq!(defines, &["VAT"]);
    assert_note(notes, "`BONES` set to 2 as well");
    // Defined by the options, or never compared: no configuration.
    let mut compile = CompileOptions::default();
    compile.defines.push(("BONES".into(), "0".into()));
    assert!(variants::flags(text, &compile)
        .iter()
        .all(|v| v.level.is_none()));
    let plain = text
        .replace("#if BONES > 1", "#ifdef SKIN")
        .replace("#if BONES > 0", "#ifdef SKIN");
    assert!(variants::flags(&plain, &CompileOptions::default())
        .iter()
        .all(|v| v.level.is_none()));
}
