//! Bad input gets errors, never a panic or a hang: random bytes, truncated shaders, token soup,
//! deep nesting, huge files.

use essl::source::SourceFile;
use essl::{compile, Stage};
use proptest::prelude::*;

const SEED: &str = include_str!("../../../../shaders-glsl/spot-smooth-nbsp.frag");
const VALID: &str = "#version 300 es\nprecision highp float;\nuniform sampler2D t;\nuniform vec3 u[2];\nin vec2 uv;\nout vec4 o;\nstruct S { vec3 a; float b[2]; };\nfloat f(inout S s, int k) { for (int i = 0; i < k; ++i) { s.a += u[i % 2]; if (s.a.x > 1.0) break; } return s.b[1]; }\nvoid main() {\n  S s = S(vec3(0.0), float[2](1.0, 2.0));\n  switch (int(uv.x * 4.0)) { case 0: o = texture(t, uv); break; default: o = vec4(f(s, 3)); }\n}\n";

fn run(src: &str, stage: Stage) -> essl::Shader {
    compile(SourceFile::new("fuzz", src), stage, &Default::default())
}

#[test]
fn every_truncation_of_real_shaders_is_handled() {
    for text in [SEED, VALID] {
        let mut cut = 0;
        while cut <= text.len() {
            if text.is_char_boundary(cut) {
                for stage in [Stage::Vertex, Stage::Fragment] {
                    let sh = run(&text[..cut], stage);
                    // Every diagnostic points inside the text.
                    for d in &sh.diagnostics {
                        assert!(
                            d.span.end as usize <= cut,
                            "span {:?} past the end at cut {cut}",
                            d.span
                        );
                    }
                }
            }
            cut += 1;
        }
    }
}

#[test]
fn indexing_a_struct_member_whose_size_is_missing_is_one_error() {
    // Found by `mutations_of_a_valid_shader_never_panic`: `float b[]` in a struct, then `s.b[1]`.
    let src = "#version 300 es\nprecision highp float;\nstruct S { float b[]; };\nout vec4 o;\nvoid main() { S s; o = vec4(s.b[1]); }\n";
    let sh = run(src, Stage::Fragment);
    let codes: Vec<&str> = sh.diagnostics.iter().map(|d| d.code).collect();
    assert_eq!(codes, ["unsized-array"]);
}

#[test]
fn ten_thousand_nested_parentheses_are_an_error() {
    let src = format!("#version 300 es\nprecision mediump float;\nout vec4 o;\nvoid main() {{ o = vec4({}1.0{}); }}\n", "(".repeat(10_000), ")".repeat(10_000));
    let sh = run(&src, Stage::Fragment);
    assert!(sh.diagnostics.iter().any(|d| d.code == "nesting-too-deep"));
    assert!(
        sh.error_count() <= 3,
        "{:?}",
        sh.diagnostics
            .iter()
            .map(|d| &d.message)
            .collect::<Vec<_>>()
    );
}

#[test]
fn deep_blocks_chains_and_macros_are_errors_not_stack_overflows() {
    let blocks = format!(
        "#version 300 es\nvoid main() {{ {} gl_Position = vec4(0.0); {} }}\n",
        "{".repeat(10_000),
        "}".repeat(10_000)
    );
    let sum = format!(
        "#version 300 es\nvoid main() {{ float x = 1.0{}; gl_Position = vec4(x); }}\n",
        " + 1.0".repeat(50_000)
    );
    let fields = format!(
        "#version 300 es\nvoid main() {{ vec4 v = vec4(1.0); float x = v{}; gl_Position = v; }}\n",
        ".xyzw.x".repeat(5_000)
    );
    let macros = format!(
        "#version 300 es\n#define A0 1.0\n{}void main() {{ gl_Position = vec4(A9999); }}\n",
        (1..10_000)
            .map(|i| format!("#define A{i} (A{} + 1.0)\n", i - 1))
            .collect::<String>()
    );
    for src in [blocks, sum, fields, macros] {
        let sh = run(&src, Stage::Vertex);
        assert!(!sh.ok());
    }
}

#[test]
fn a_ten_megabyte_file_is_handled() {
    let mut src = String::from(
        "#version 300 es\nprecision highp float;\nout vec4 o;\nvoid main() {\n  float x = 0.0;\n",
    );
    while src.len() < 10 * 1024 * 1024 {
        src.push_str(
            "  // a long comment line that pads the file to ten megabytes, as generated code can\n",
        );
        src.push_str("  x += 1.0;\n");
    }
    src.push_str("  o = vec4(x);\n}\n");
    let sh = run(&src, Stage::Fragment);
    assert!(sh.ok(), "{:?}", sh.diagnostics.first());
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    #[test]
    fn random_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        let text = String::from_utf8_lossy(&bytes);
        let _ = run(&format!("#version 300 es\n{text}"), Stage::Fragment);
        let _ = run(&text, Stage::Vertex);
    }

    #[test]
    fn token_soup_never_panics(words in proptest::collection::vec(prop::sample::select(vec![
        "float", "vec3", "int", "uint", "bool", "mat4", "struct", "S", "x", "y", "main", "void", "in", "out",
        "uniform", "const", "precision", "highp", "if", "else", "for", "while", "do", "switch", "case",
        "default", "break", "continue", "return", "discard", "(", ")", "{", "}", "[", "]", ";", ",", ".",
        "=", "+=", "+", "-", "*", "/", "%", "<<", "==", "&&", "?", ":", "!", "~", "++", "1", "2.0", "3u",
        "true", "sampler2D", "texture", "#define", "#if", "#endif", "\n", "length", "xyz", "layout",
        "location", "flat", "invariant", "gl_Position", "gl_FragCoord",
    ]), 0..120)) {
        let body = words.join(" ");
        let _ = run(&format!("#version 300 es\nprecision mediump float;\n{body}"), Stage::Fragment);
        let _ = run(&format!("#version 300 es\nvoid main() {{ {body} }}"), Stage::Vertex);
    }

    #[test]
    fn mutations_of_a_valid_shader_never_panic(pos in 0usize..VALID.len(), insert in prop::sample::select(vec!["", ";", "{", "}", "(", ")", "[0]", ".x", " float ", "1", "*", "=", "#", "\u{a0}", "\\\n"]), delete in 0usize..8) {
        let mut s = VALID.to_string();
        let mut p = pos;
        while !s.is_char_boundary(p) { p -= 1; }
        let mut end = (p + delete).min(s.len());
        while !s.is_char_boundary(end) { end -= 1; }
        s.replace_range(p..end, insert);
        let _ = run(&s, Stage::Fragment);
    }
}

/// The deepest shaders the parser admits, one per kind of nesting (256 levels at most).
fn deepest_shaders() -> Vec<(&'static str, String)> {
    let n = 250;
    let fs = |body: String| {
        format!("#version 300 es\nprecision highp float;\nout vec4 o;\nuniform float u;\n{body}\n")
    };
    vec![
        (
            "parentheses",
            fs(format!(
                "void main() {{ o = vec4({}u{}); }}",
                "(".repeat(n),
                ")".repeat(n)
            )),
        ),
        (
            "blocks",
            fs(format!(
                "void main() {{ {} o = vec4(u); {} }}",
                "{".repeat(n),
                "}".repeat(n)
            )),
        ),
        (
            "sum",
            fs(format!(
                "void main() {{ float x = u{}; o = vec4(x); }}",
                " + u".repeat(n)
            )),
        ),
        (
            "calls",
            fs(format!(
                "void main() {{ o = vec4({}u{}); }}",
                "sin(".repeat(n),
                ")".repeat(n)
            )),
        ),
        (
            "constructors",
            fs(format!(
                "void main() {{ o = {}vec4(u){}; }}",
                "vec4(".repeat(n),
                ")".repeat(n)
            )),
        ),
        (
            "else-ifs",
            fs(format!(
                "void main() {{ o = vec4(0.0); {} o = vec4(1.0); }}",
                "if (u > 0.0) o.x += 1.0; else ".repeat(n)
            )),
        ),
        (
            "constant",
            fs(format!(
                "const float c = {}1.0{};\nvoid main() {{ o = vec4(c * u); }}",
                "(".repeat(n),
                " + 1.0)".repeat(n)
            )),
        ),
        (
            "for loops",
            fs(format!(
                "void main() {{ float x = 0.0; {} x += u; o = vec4(x); }}",
                "for (int i = 0; i < 2; i++) ".repeat(n)
            )),
        ),
        (
            "while loops",
            fs(format!(
                "void main() {{ float x = 0.0; int i = 0; {} x += u; o = vec4(x); }}",
                "while (i++ < 2) ".repeat(n)
            )),
        ),
    ]
}

#[test]
fn the_deepest_shaders_compile_and_link_from_a_small_thread() {
    // `compile` and `link` switch to a stack segment of `COMPILE_STACK` bytes when the caller's
    // thread has less left; 128 KiB forces that path for every shader.
    let handle = std::thread::Builder::new()
        .stack_size(128 << 10)
        .spawn(|| {
            let vs = run(
                "#version 300 es\nvoid main() { gl_Position = vec4(0.0); }\n",
                Stage::Vertex,
            );
            let mut failed = Vec::new();
            for (kind, src) in deepest_shaders() {
                let fs = run(&src, Stage::Fragment);
                let program = essl::link::link(&vs, &fs);
                if !fs.ok() || !program.ok {
                    failed.push((kind, fs.diagnostics.first().map(|d| d.message.clone())));
                }
            }
            failed
        })
        .unwrap();
    let failed = handle.join().unwrap();
    assert!(failed.is_empty(), "{failed:?}");
}

#[test]
fn oversized_variables_are_user_errors_with_webgl_limits() {
    // Chromium's answers for these: tests/oracle/PROBES.md, "Variable size limits".
    let fs = |body: &str| format!("#version 300 es\nprecision highp float;\nout vec4 o;\n{body}\n");
    let cases = [
        (
            "void main() { int a[2147483647]; a[0] = 1; o = vec4(float(a[0])); }",
            "variable-too-large",
            "`a` takes 32.0 GiB laid out as a std140 block member, and WebGL implementations allow less than 2 GiB for one variable",
        ),
        (
            "void main() { float a[16384]; a[0] = 1.0; o = vec4(a[0]); }",
            "private-variable-too-large",
            "`a` takes 64 KiB, and WebGL implementations allow less than 64 KiB for a local, global, constant, parameter or varying",
        ),
        (
            "float f(float p[16384]) { return p[0]; }\nvoid main() { o = vec4(1.0); }",
            "private-variable-too-large",
            "`p` takes 64 KiB, and WebGL implementations allow less than 64 KiB for a local, global, constant, parameter or varying",
        ),
    ];
    for (body, code, message) in cases {
        let sh = run(&fs(body), Stage::Fragment);
        let errors: Vec<(&str, &str)> = sh
            .diagnostics
            .iter()
            .filter(|d| d.is_error())
            .map(|d| (d.code, d.message.as_str()))
            .collect();
        assert_eq!(errors, [(code, message)], "{body}");
    }
    let many = (0..263)
        .map(|i| format!("vec4 a{i}[4000];"))
        .collect::<String>();
    let sh = run(
        &fs(&format!("void main() {{ {many} o = vec4(1.0); }}")),
        Stage::Fragment,
    );
    let codes: Vec<&str> = sh.diagnostics.iter().map(|d| d.code).collect();
    assert_eq!(codes, ["private-variables-too-large"]);
    let sh = run(
        &fs("void main() { float a[16383]; a[0] = 1.0; o = vec4(a[0]); }"),
        Stage::Fragment,
    );
    assert!(sh.ok(), "{:?}", sh.diagnostics.first());
}

#[test]
fn a_flood_of_errors_is_capped_with_a_count() {
    let src = format!("#version 300 es\nprecision mediump float;\nout vec4 o;\nvoid main() {{ {} o = vec4(1.0); }}\n", "@ ".repeat(5000));
    let sh = run(&src, Stage::Fragment);
    assert_eq!(sh.diagnostics.len(), essl::diagnostic::MAX_DIAGNOSTICS + 1);
    let last = sh.diagnostics.last().unwrap();
    assert_eq!(last.code, "too-many-diagnostics");
    assert!(
        last.is_error(),
        "errors were dropped: the shader must still fail"
    );
    assert!(last.message.starts_with("at least "), "{}", last.message);
    assert!(!sh.ok());
}

#[test]
fn a_fix_on_a_long_line_is_not_previewed_in_the_help() {
    // Each of these 100 errors would otherwise repeat the whole line in its help.
    let src = format!("#version 300 es\nprecision mediump float;\nout vec4 o;\nvoid main() {{ float x; {} o = vec4(x); }}\n", "x = 1;".repeat(100));
    let sh = run(&src, Stage::Fragment);
    let helps: Vec<String> = sh
        .diagnostics
        .iter()
        .filter_map(|d| d.help_text(&sh.file))
        .collect();
    assert_eq!(helps.len(), 100);
    assert!(
        helps.iter().all(|h| h == "write a float literal: `1.0`"),
        "{}",
        helps[0]
    );
    // A short line still shows its fixed text.
    let sh = run("#version 300 es\nprecision mediump float;\nout vec4 o;\nvoid main() {\n  float x = 1;\n  o = vec4(x);\n}\n", Stage::Fragment);
    let help = sh.diagnostics[0].help_text(&sh.file).unwrap();
    assert_eq!(help, "write a float literal: `1.0`: `float x = 1.0;`");
}
