//! One case per GLSL ES 3.00 / WebGL2 rule. Each case is a shader whose expected diagnostics
//! are written under the line they point at, as rust-analyzer's tests do:
//!
//! ```text
//! float x = 1;
//!           //^ error type-mismatch  (the `//` starts under the `1`)
//! ```
//!
//! A `//^` comment names the severity and code of a diagnostic whose primary span starts on
//! the line above, at the column where the comment's first `/` is. Cases with no annotation must compile cleanly.

use essl::source::SourceFile;
use essl::{compile, Stage};

/// Parses expected diagnostics from the annotations: (line, column, severity, code).
fn expectations(src: &str) -> Vec<(u32, u32, String, String)> {
    let mut out = Vec::new();
    for (i, line) in src.lines().enumerate() {
        let trimmed = line.trim_start();
        if let Some(rest) = trimmed.strip_prefix("//^") {
            // The annotation's first `/` sits under the column it points at.
            let col = line.find("//^").unwrap() as u32 + 1;
            let mut parts = rest.split_whitespace();
            let sev = parts.next().unwrap().to_string();
            let code = parts.next().unwrap().to_string();
            out.push((i as u32, col, sev, code));
        }
    }
    out
}

#[track_caller]
fn check(stage: Stage, src: &str) {
    let sh = compile(SourceFile::new("case", src), stage, &Default::default());
    let want = expectations(src);
    let got: Vec<(u32, u32, String, String)> = sh
        .diagnostics
        .iter()
        .map(|d| {
            let lc = sh.file.line_col(d.span.start);
            (
                lc.line,
                lc.column,
                d.severity.as_str().to_string(),
                d.code.to_string(),
            )
        })
        .collect();
    let describe = |v: &[(u32, u32, String, String)]| {
        v.iter()
            .map(|(l, c, s, k)| format!("{l}:{c} {s} {k}"))
            .collect::<Vec<_>>()
            .join("\n  ")
    };
    let all: Vec<String> = sh
        .diagnostics
        .iter()
        .map(|d| format!("{}: {}", d.code, d.message))
        .collect();
    assert_eq!(
        describe(&got),
        describe(&want),
        "\nmessages:\n  {}",
        all.join("\n  ")
    );
}

fn frag(body: &str) -> String {
    format!("#version 300 es\nprecision mediump float;\nout vec4 o;\n{body}")
}

// ----- what WebGL2 accepts -----

#[test]
fn accepts_precision_qualifiers_everywhere_es_allows_them() {
    check(Stage::Fragment, &frag("highp float f(mediump float x, lowp int n) { return x * float(n); }\nvoid main() { precision highp float; o = vec4(f(1.0, 2)); }\n"));
}

#[test]
fn accepts_loose_uniforms_of_every_type() {
    check(
        Stage::Fragment,
        &frag(
            "struct L { vec3 p; float k[2]; };\nuniform float a; uniform vec2 b; uniform ivec3 c; uniform uvec4 d; uniform bool e; uniform bvec2 g;\nuniform mat2 m2; uniform mat3x4 m34; uniform float arr[3]; uniform L l; uniform L ls[2];\nvoid main() { o = vec4(a + b.x + float(c.x) + float(d.x) + (e ? 1.0 : 0.0) + (g.x ? 1.0 : 0.0) + m2[0][0] + m34[0][0] + arr[1] + l.p.x + ls[1].k[1]); }\n",
        ),
    );
}

#[test]
fn accepts_uniform_blocks_and_unlocated_inputs_and_outputs() {
    check(
        Stage::Vertex,
        "#version 300 es\nlayout(std140) uniform Light { vec4 color; mat4 m; } light;\nuniform Other { float k; };\nin vec4 a_position;\nin vec3 a_normal;\nout vec3 v_normal;\nflat out int v_id;\nvoid main() { v_normal = a_normal * k; v_id = gl_VertexID + gl_InstanceID; gl_Position = light.m * a_position + light.color; }\n",
    );
}

#[test]
fn accepts_every_sampler_type_including_as_parameters() {
    check(
        Stage::Fragment,
        &frag(
            "uniform sampler2D s2; uniform samplerCube sc; uniform highp sampler3D s3; uniform highp sampler2DArray sa;\nuniform highp sampler2DShadow ss; uniform highp samplerCubeShadow scs; uniform highp sampler2DArrayShadow sas;\nuniform highp isampler2D i2; uniform highp usampler3D u3; uniform highp isamplerCube ic; uniform highp usampler2DArray ua;\nvec4 look(sampler2D t, vec2 uv) { return texture(t, uv); }\nvoid main() {\n  o = look(s2, vec2(0.5)) + texture(sc, vec3(1.0)) + texture(s3, vec3(0.5)) + texture(sa, vec3(0.5)) +\n      vec4(texture(ss, vec3(0.5)) + texture(scs, vec4(0.5)) + texture(sas, vec4(0.5))) +\n      vec4(texelFetch(i2, ivec2(0), 0)) + vec4(texelFetch(u3, ivec3(0), 0)) + vec4(textureSize(ic, 0).x) + vec4(texture(ua, vec3(0.5)));\n}\n",
        ),
    );
}

#[test]
fn accepts_defines_and_conditionals() {
    check(Stage::Fragment, "#version 300 es\n#define SCALE 2.0\n#if defined(GL_ES) && __VERSION__ == 300\nprecision highp float;\n#else\n#error not ES 3.00\n#endif\nout vec4 o;\nvoid main() { o = vec4(SCALE); }\n");
}

#[test]
fn user_defines_come_from_the_api() {
    let src =
        "#version 300 es\nprecision highp float;\nout vec4 o;\nvoid main() { o = vec4(LIGHTS); }\n";
    let opts = essl::CompileOptions {
        defines: vec![("LIGHTS".into(), "3.0".into())],
    };
    let sh = compile(SourceFile::new("t", src), Stage::Fragment, &opts);
    assert!(sh.ok(), "{:?}", sh.diagnostics);
    let without = compile(
        SourceFile::new("t", src),
        Stage::Fragment,
        &Default::default(),
    );
    assert_eq!(without.diagnostics[0].code, "undeclared-identifier");
}

// ----- what WebGL2 rejects -----

#[test]
fn implicit_conversions() {
    check(Stage::Fragment, &frag("void main() {\n  float x = 1;\n            //^ error type-mismatch\n  uint u = 3;\n           //^ error type-mismatch\n  o = vec4(x) * float(u);\n}\n"));
}

#[test]
fn missing_default_float_precision_in_a_fragment_shader() {
    check(Stage::Fragment, "#version 300 es\nout vec4 o;\n         //^ error missing-precision\nvoid main() { o = vec4(1.0); }\n");
}

#[test]
fn samplers_without_default_precision() {
    check(Stage::Vertex, "#version 300 es\nuniform sampler3D s;\n                  //^ error missing-precision\nvoid main() { gl_Position = texture(s, vec3(0.0)); }\n");
}

#[test]
fn recursion_even_in_functions_never_called() {
    check(
        Stage::Fragment,
        &frag("float g(float x);\nfloat f(float x) { return g(x); }\nfloat g(float x) { return f(x); }\n      //^ error recursion\nvoid main() { o = vec4(1.0); }\n"),
    );
}

#[test]
fn reserved_words_and_names() {
    check(
        Stage::Fragment,
        &frag("void main() {\n  float class = 1.0;\n        //^ error reserved-word\n  float gl_x = 1.0;\n        //^ error reserved-name\n  float a__b = 1.0;\n        //^ error reserved-name\n  o = vec4(gl_x);\n}\n"),
    );
}

#[test]
fn es100_names() {
    check(
        Stage::Vertex,
        "#version 300 es\nattribute vec4 a;\n//^ error es100-qualifier\nvarying vec4 v;\n//^ error es100-qualifier\nuniform sampler2D s;\nvoid main() { v = texture2D(s, a.xy); gl_Position = a; }\n                  //^ error undeclared-function\n",
    );
    check(Stage::Fragment, &frag("void main() { gl_FragColor = vec4(1.0); }\n              //^ error undeclared-identifier\n"));
}

#[test]
fn writes_to_uniforms_and_inputs() {
    check(
        Stage::Fragment,
        &frag("uniform float u;\nin float v;\nvoid main() {\n  u = 1.0;\n  //^ error not-assignable\n  v = 2.0;\n  //^ error not-assignable\n  o = vec4(u + v);\n}\n"),
    );
}

#[test]
fn dynamic_sampler_indexing() {
    check(
        Stage::Fragment,
        &frag("uniform sampler2D t[3];\nuniform int k;\nvoid main() {\n  const int c = 1;\n  o = texture(t[c + 1], vec2(0.0));\n  for (int i = 0; i < 3; i++) { o += texture(t[i], vec2(0.0)); }\n                                               //^ error dynamic-sampler-index\n}\n"),
    );
}

#[test]
fn several_fragment_outputs_need_locations() {
    check(Stage::Fragment, "#version 300 es\nprecision mediump float;\nout vec4 a;\n         //^ error output-location-required\nout vec4 b;\n         //^ error output-location-required\nvoid main() { a = vec4(1.0); b = a; }\n");
    check(Stage::Fragment, "#version 300 es\nprecision mediump float;\nlayout(location = 0) out vec4 a;\nlayout(location = 1) out vec4 b;\nvoid main() { a = vec4(1.0); b = a; }\n");
}

#[test]
fn integer_varyings_must_be_flat() {
    check(Stage::Vertex, "#version 300 es\nout int v_i;\n        //^ error integer-varying-not-flat\nvoid main() { v_i = 1; gl_Position = vec4(0.0); }\n");
    check(Stage::Fragment, &frag("in uvec2 v_u;\n         //^ error integer-varying-not-flat\nvoid main() { o = vec4(v_u.x); }\n"));
}

#[test]
fn version_must_be_on_the_first_line() {
    check(Stage::Fragment, "\n#version 300 es\n//^ error version-not-first-line\nprecision mediump float;\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n");
}

#[test]
fn wrong_overloads_of_builtins() {
    check(
        Stage::Fragment,
        &frag("void main() {\n  vec3 v = vec3(1.0);\n  o = vec4(pow(v, 2.0), 1.0);\n           //^ error no-matching-overload\n  o += vec4(smoothstep(v, v, 0.5), 1.0);\n            //^ error no-matching-overload\n  o += vec4(smoothstep(0.0, 1.0, v), 1.0);\n}\n"),
    );
}

#[test]
fn missing_semicolons_are_reported_at_the_end_of_the_line_that_lacks_them() {
    check(
        Stage::Fragment,
        &frag("uniform float a\n               //^ error missing-semicolon\nuniform float b;\nvoid main() {\n  float x = a + b\n                 //^ error missing-semicolon\n  o = vec4(x);\n}\n"),
    );
}

#[test]
fn every_syntax_error_in_one_run_without_cascades() {
    check(
        Stage::Fragment,
        &frag("void main() {\n  float x = (1.0 + ;\n                   //^ error syntax-error\n  float y = 2.0 * * 3.0;\n                  //^ error syntax-error\n  o = vec4(x + y);\n}\n"),
    );
}

#[test]
fn discard_only_in_fragment_shaders() {
    check(Stage::Vertex, "#version 300 es\nvoid main() { discard; gl_Position = vec4(0.0); }\n              //^ error discard-in-vertex\n");
}

#[test]
fn constant_expressions() {
    check(
        Stage::Fragment,
        &frag("uniform float u;\nconst float c = sin(1.0);\nfloat g = u * 2.0;\n          //^ error non-constant-initializer\nvoid main() {\n  float a[3];\n  a[3] = c;\n    //^ error index-out-of-range\n  int n = 1 / 0;\n          //^ warning division-by-zero\n  o = vec4(a[0] + g + float(n));\n}\n"),
    );
}

#[test]
fn swizzles() {
    check(
        Stage::Fragment,
        &frag("void main() {\n  float f = 1.0;\n  vec2 v = vec2(f);\n  o.x = f.x;\n          //^ error invalid-field\n  o.y = v.xyzw.x;\n          //^ error invalid-swizzle\n  o.z = v.xg.x;\n          //^ error invalid-swizzle\n  v.xx = vec2(1.0);\n  //^ error not-assignable\n}\n"),
    );
}

#[test]
fn switch_rules() {
    check(
        Stage::Fragment,
        &frag("uniform int k;\nvoid main() {\n  switch (k) {\n    case 1: o = vec4(1.0); break;\n    case 1: break;\n    //^ error duplicate-case\n    default:\n  }\n  //^ error label-at-end-of-switch\n}\n"),
    );
}

#[test]
fn webgl_forbids_ternary_and_sequence_on_arrays() {
    check(Stage::Fragment, &frag("void main() {\n  float a[2]; float b[2];\n  float c[2] = true ? a : b;\n               //^ error webgl-forbidden-operand\n  o = vec4(c[0]);\n}\n"));
}

#[test]
fn no_break_spaces_are_one_error_per_line_and_harmless_in_comments() {
    let src = "#version 300 es\u{a0}\nprecision mediump float; // note\u{a0}\nout vec4 o;\nvoid main() {\n\u{a0}\u{a0}o = vec4(1.0);\n}\n";
    let sh = compile(
        SourceFile::new("t", src),
        Stage::Fragment,
        &Default::default(),
    );
    let got: Vec<(u32, &str, usize)> = sh
        .diagnostics
        .iter()
        .map(|d| {
            (
                sh.file.line_col(d.span.start).line,
                d.severity.as_str(),
                d.fix.as_ref().map_or(0, |f| f.edits.len()),
            )
        })
        .collect();
    // Line 5's two adjacent no-break spaces are one run: one edit that writes two spaces.
    assert_eq!(got, [(1, "error", 1), (2, "warning", 1), (5, "error", 1)]);
}
