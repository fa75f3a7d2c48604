//! Shaders inside host files: found, placed on the host's lines, paired, and sharing one copy
//! of the host's text however many there are.

use std::sync::Arc;

use essl_check::{CheckOptions, Overrides};

use crate::{check, lines, write};

#[test]
fn a_page_of_many_shaders_shares_its_text_and_pairs_by_name() {
    let dir = tempfile::tempdir().unwrap();
    let mut page = String::new();
    for i in 0..500 {
        page.push_str(&format!(
            "<script id=\"s{i}-vertex-shader\" type=\"x-shader/x-vertex\">#version 300 es\nin vec4 p;\nvoid main() {{ gl_Position = p; }}\n</script>\n\
             <script id=\"s{i}-fragment-shader\" type=\"x-shader/x-fragment\">#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() {{ c = vec4({i}.0); }}\n</script>\n"
        ));
    }
    // One broken shader, to see where its error lands.
    page.push_str("<script id=\"bad-fragment-shader\" type=\"x-shader/x-fragment\">#version 300 es\nvoid main() { x = 1; }\n</script>\n");
    write(dir.path(), &[("page.html", &page)]);
    let run = check(dir.path(), Overrides::default(), CheckOptions::default());
    let unit = &run.results[0];
    assert_eq!(unit.shaders.len(), 1001);
    assert_eq!(unit.programs.len(), 500);
    let first = unit.shaders[0].file();
    assert!(unit.shaders.iter().all(|s| Arc::ptr_eq(s.file(), first)));
    let line = page.lines().count() - 1;
    assert_eq!(
        lines(dir.path(), &run),
        [format!("page.html:{line}:15 undeclared-identifier")]
    );
    assert_eq!(
        unit.shaders[1000].label(),
        format!("{}:{}", dir.path().join("page.html").display(), line - 1)
    );
}

#[test]
fn a_js_file_and_a_shader_file_in_one_run() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        &[
            ("app.js", "const fs = `#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() { c = vec4(1) }`;\n"),
            ("a.vert", "#version 300 es\nvoid main() { gl_Position = vec4(0); }\n"),
        ],
    );
    let run = check(dir.path(), Overrides::default(), CheckOptions::default());
    assert_eq!(lines(dir.path(), &run), ["app.js:4:26 missing-semicolon"]);
}

/// Where a diagnostic lands in a script, as `LINE:COL code`, and the fixed script.
fn script(text: &str) -> (Vec<String>, Option<String>) {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), &[("s.js", text)]);
    let run = check(dir.path(), Overrides::default(), CheckOptions::default());
    let found = lines(dir.path(), &run)
        .into_iter()
        .map(|l| l.trim_start_matches("s.js:").to_string())
        .collect();
    let fixing = CheckOptions {
        fix: essl_check::FixMode::Certain,
        ..CheckOptions::default()
    };
    let fixed = check(dir.path(), Overrides::default(), fixing);
    let after = fixed.results[0].fixed.first().map(|f| f.after.clone());
    (found, after)
}

#[test]
fn after_a_line_continuation() {
    let text = "export default `\\\n#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() { c = vec4(1) }`;\n";
    let (found, fixed) = script(text);
    assert_eq!(found, ["5:26 missing-semicolon"]);
    assert_eq!(fixed.unwrap(), text.replace("vec4(1) }", "vec4(1); }"));
}

#[test]
fn after_a_unicode_escape() {
    // `\u{41}` is `A`: the error after it is placed past the escape's six bytes.
    let text = "const fs = `#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() { float \\u{41} = 1.0; c = vec4(B); }`;\n";
    let (found, fixed) = script(text);
    assert_eq!(found, ["4:44 undeclared-identifier"]);
    assert_eq!(fixed, None, "nothing to fix: the file stays as it is");
}

#[test]
fn escaped_line_breaks_in_one_line() {
    let text = "const fs = `#version 300 es\\nprecision highp float;\\nout vec4 c;\\nvoid main() { c = vec4(1) }`;\n";
    let (found, fixed) = script(text);
    assert_eq!(found, ["1:92 missing-semicolon"]);
    assert_eq!(fixed.unwrap(), text.replace("vec4(1) }", "vec4(1); }"));
}

#[test]
fn inside_a_joined_array() {
    let text = "const fs = [\n  '#version 300 es',\n  'precision highp float;',\n  'out vec4 c;',\n  'void main() { c = vec4(1) }',\n].join('\\n');\n";
    let (found, fixed) = script(text);
    assert_eq!(found, ["5:29 missing-semicolon"]);
    assert_eq!(fixed.unwrap(), text.replace("vec4(1) }", "vec4(1); }"));
}

#[test]
fn a_fix_inside_an_escape_is_refused_and_says_so() {
    // `\u00a0` is a no-break space; its fix would replace what the escape stands for.
    let text = r#"const fs = `#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() {\u00a0c = vec4(1.0); }`;"#;
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), &[("s.js", text)]);
    let run = check(dir.path(), Overrides::default(), CheckOptions::default());
    let s = &run.results[0].shaders[0];
    let (_, d) = s.all().next().unwrap();
    assert_eq!(d.code, "no-break-space");
    assert!(d.fix.is_none());
    assert!(
        d.notes.iter().any(|n| n.contains("escape")),
        "{:?}",
        d.notes
    );
    // An insertion just before an escape edits the file: `;` before `\n`.
    let text = r#"const fs = `#version 300 es\nprecision highp float;\nout vec4 c\nvoid main() { c = vec4(1.0); }`;"#;
    let (found, fixed) = script(text);
    assert_eq!(found, ["1:64 missing-semicolon"]);
    assert!(fixed.unwrap().contains(r"out vec4 c;\nvoid"));
}

#[test]
fn a_constant_and_an_imported_chunk_are_followed() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        &[
            ("main.glsl.ts", "export default `\\\nvoid main() { c = vec4(K) }\n`;\n"),
            (
                "layer.ts",
                "import main from './main.glsl';\nconst HEAD = `precision highp float;`;\nexport const fs = `\\\n#version 300 es\n${HEAD}\nconst float K = 1.0;\nout vec4 c;\n${main}`;\n",
            ),
        ],
    );
    let run = check(dir.path(), Overrides::default(), CheckOptions::default());
    assert_eq!(
        lines(dir.path(), &run),
        ["main.glsl.ts:2:26 missing-semicolon"]
    );
}

#[test]
fn a_chunk_is_checked_as_a_library() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        &[(
            "module.js",
            "export const vs = /* glsl */ `\\\nuniform projectUniforms { mat4 m; } project;\nvec4 project_position(vec4 p) { return project.m * p * fp32_scale(p.w); }\nfloat broken() { return 1.0 }\n`;\n",
        )],
    );
    let run = check(dir.path(), Overrides::default(), CheckOptions::default());
    assert_eq!(
        lines(dir.path(), &run),
        ["module.js:4:28 missing-semicolon"]
    );
}

/// A check without the lints answers as WebGL does, from the front end and the linker: the
/// shaders are not lowered to naga IR (which only the lints and the translators read). With
/// the lints a shader is lowered where a lint on the IR has something to look at (the fragment
/// shader's division, not the vertex shader's constant position), and the lints' findings land
/// on the file; with every rule allowed (`--allow all`), nothing is lowered.
#[test]
fn only_a_check_with_lints_lowers() {
    let dir = tempfile::tempdir().unwrap();
    let frag = "#version 300 es\nprecision highp float;\nuniform float u_a, u_b;\nout vec4 c;\nvoid main() { c = vec4(1.0 / (u_a - u_b)); }\n";
    write(
        dir.path(),
        &[
            (
                "a.vert",
                "#version 300 es\nvoid main() { gl_Position = vec4(0); }\n",
            ),
            ("a.frag", frag),
        ],
    );
    let without = CheckOptions {
        lints: false,
        ..CheckOptions::default()
    };
    let mut allowed = Overrides::default();
    allowed.rule("all", essl_lint::Level::Allow).unwrap();
    for (overrides, options, lowered, found) in [
        (
            Overrides::default(),
            without,
            [false, false],
            Vec::<String>::new(),
        ),
        (
            Overrides::default(),
            CheckOptions::default(),
            [false, true],
            vec!["a.frag:5:30 division-by-difference".to_string()],
        ),
        (allowed, CheckOptions::default(), [false, false], Vec::new()),
    ] {
        let run = check(dir.path(), overrides, options);
        let unit = &run.results[0];
        assert_eq!(unit.programs.len(), 1, "the pair is linked either way");
        assert_eq!(unit.shaders.len(), 2);
        for s in &unit.shaders {
            let s = s.shader.as_ref().unwrap();
            let expected = lowered[usize::from(s.stage == essl::Stage::Fragment)];
            assert_eq!(s.naga.is_some(), expected, "{:?}", s.stage);
        }
        assert_eq!(lines(dir.path(), &run), found);
    }
}
