//! The `essl` binary end to end: exit statuses, usage and I/O errors, JSON shape, `--fix`.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .canonicalize()
        .unwrap()
}

fn essl(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_essl"))
        .args(args)
        .current_dir(dir)
        .env_remove("CLICOLOR_FORCE")
        .output()
        .expect("the essl binary runs")
}

fn stdout(o: &Output) -> String {
    String::from_utf8(o.stdout.clone()).unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8(o.stderr.clone()).unwrap()
}

const GOOD_VERT: &str =
    "#version 300 es\nin vec4 a_position;\nvoid main() {\n    gl_Position = a_position;\n}\n";
const GOOD_FRAG: &str = "#version 300 es\nprecision highp float;\nuniform vec4 u_color;\nout vec4 color;\nvoid main() {\n    color = u_color;\n}\n";

#[test]
fn clean_shaders_exit_0() {
    let o = essl(
        &[
            "lint",
            "--color",
            "never",
            "shaders-glsl/spot-step.vert",
            "shaders-glsl/spot-step.frag",
        ],
        &repo_root(),
    );
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    assert_eq!(stdout(&o), "linked `shaders-glsl/spot-step.vert` + `shaders-glsl/spot-step.frag`: 9 active uniforms, 2 active attributes\n2 files, 0 errors, 0 warnings, 1 program linked\n");
}

#[test]
fn errors_exit_1() {
    let o = essl(
        &[
            "lint",
            "--color",
            "never",
            "shaders-glsl/spot-smooth-nbsp.frag",
        ],
        &repo_root(),
    );
    assert_eq!(o.status.code(), Some(1));
    let out = stdout(&o);
    assert!(out.contains("error[missing-semicolon]"), "{out}");
    assert!(
        out.contains("--> shaders-glsl/spot-smooth-nbsp.frag:19:27"),
        "{out}"
    );
    assert!(out.lines().last().unwrap().starts_with("1 file, "), "{out}");
    assert!(!out.contains('\x1b'), "no colour when piped");
}

#[test]
fn color_always_colours() {
    let o = essl(
        &[
            "lint",
            "--color",
            "always",
            "shaders-glsl/spot-smooth-nbsp.frag",
        ],
        &repo_root(),
    );
    assert!(stdout(&o).contains('\x1b'));
}

#[test]
fn missing_file_exits_2_and_checks_the_rest() {
    let o = essl(
        &["lint", "no/such/file.frag", "shaders-glsl/spot-step.frag"],
        &repo_root(),
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("cannot read `no/such/file.frag`: no such file or directory"),
        "{}",
        stderr(&o)
    );
    assert!(stdout(&o).contains("1 file, 0 errors"), "{}", stdout(&o));
}

#[test]
fn unknown_extension_is_a_usage_error_unless_stage_is_given() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("shader.glsl"), GOOD_FRAG).unwrap();
    let o = essl(&["lint", "shader.glsl"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("cannot tell the stage of `shader.glsl`"),
        "{}",
        stderr(&o)
    );
    assert!(stderr(&o).contains("--stage"), "{}", stderr(&o));
    let o = essl(&["lint", "--stage", "fragment", "shader.glsl"], dir.path());
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    // In a folder, a `.glsl` file nothing places is an error naming it, not skipped…
    let o = essl(&["lint", "."], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("cannot tell the stage of `shader.glsl`: name it"),
        "{}",
        stderr(&o)
    );
    // …until a pragma (or `NAME.frag.glsl`, or essl.toml's `[stages]`) says it.
    let pragma = GOOD_FRAG.replace("precision", "#pragma essl stage(fragment)\nprecision");
    std::fs::write(dir.path().join("shader.glsl"), pragma).unwrap();
    std::fs::write(dir.path().join("b.vert.glsl"), GOOD_VERT).unwrap();
    std::fs::write(dir.path().join("notes.txt"), "not a shader").unwrap();
    let o = essl(&["lint", "--color", "never", "."], dir.path());
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    assert!(stdout(&o).contains("2 files, 0 errors"), "{}", stdout(&o));
}

#[test]
fn a_run_that_finds_no_shader_says_so() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("notes.txt"), "not a shader").unwrap();
    std::fs::write(dir.path().join("page.html"), "<p>no script</p>").unwrap();
    let o = essl(&["lint", "."], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(
        stderr(&o),
        "error: no shaders found in `.` (looked for .vert, .frag, .vs, .fs, .vsh, .fsh, .glsl \
         files, and shaders inside .html, .js and .ts files)\n"
    );
}

#[test]
fn gitignore_and_excludes_leave_files_out() {
    let dir = tempfile::tempdir().unwrap();
    for name in ["a.frag", "build/b.frag", "vendor/c.frag", "d.old.frag"] {
        let path = dir.path().join(name);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, GOOD_FRAG).unwrap();
    }
    std::fs::write(dir.path().join(".gitignore"), "build/\n").unwrap();
    std::fs::write(dir.path().join("essl.toml"), "exclude = [\"vendor/**\"]\n").unwrap();
    let files = |args: &[&str]| -> Vec<String> {
        let mut all = vec!["lint", "--format", "json"];
        all.extend_from_slice(args);
        all.push(".");
        let o = essl(&all, dir.path());
        stdout(&o)
            .lines()
            .map(|l| serde_json::from_str::<serde_json::Value>(l).unwrap())
            .filter_map(|v| v["file"].as_str().map(str::to_string))
            .collect()
    };
    assert_eq!(files(&[]), ["a.frag", "d.old.frag"]);
    assert_eq!(files(&["--extend-exclude", "*.old.frag"]), ["a.frag"]);
    // `--exclude` replaces essl.toml's list.
    assert_eq!(
        files(&["--exclude", "*.old.frag"]),
        ["a.frag", "vendor/c.frag"]
    );
}

#[test]
fn bad_arguments_exit_2() {
    let root = repo_root();
    assert_eq!(essl(&["lint"], &root).status.code(), Some(2));
    assert_eq!(
        essl(&["lint", "--format", "xml", "shaders-glsl"], &root)
            .status
            .code(),
        Some(2)
    );
    assert_eq!(
        essl(&["lint", "-D", "1X", "shaders-glsl"], &root)
            .status
            .code(),
        Some(2)
    );
    assert_eq!(essl(&["frobnicate"], &root).status.code(), Some(2));
}

#[test]
fn non_utf8_file_exits_2_naming_the_offset() {
    let dir = tempfile::tempdir().unwrap();
    let mut bytes = b"#version 300 es\n// caf".to_vec();
    bytes.push(0xE9); // Latin-1 é
    bytes.extend_from_slice(b"\nvoid main() {}\n");
    std::fs::write(dir.path().join("latin1.frag"), &bytes).unwrap();
    let o = essl(&["lint", "latin1.frag"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(err.contains("latin1.frag"), "{err}");
    assert!(
        err.contains("not UTF-8") && err.contains("offset 22"),
        "{err}"
    );
    // --fix never touches it.
    let o = essl(&["lint", "--fix", "latin1.frag"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(
        std::fs::read(dir.path().join("latin1.frag")).unwrap(),
        bytes
    );
}

#[test]
fn huge_file_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("huge.frag");
    let f = std::fs::File::create(&path).unwrap();
    f.set_len(16 * 1024 * 1024 + 1).unwrap();
    let o = essl(&["lint", "huge.frag"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("huge.frag") && stderr(&o).contains("16 MiB"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn warnings_pass_unless_denied() {
    let dir = tempfile::tempdir().unwrap();
    let text = GOOD_VERT.replace("in vec4", "// a\u{a0}comment\nin vec4");
    std::fs::write(dir.path().join("w.vert"), text).unwrap();
    let o = essl(&["lint", "w.vert"], dir.path());
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    assert!(stdout(&o).contains("1 warning"), "{}", stdout(&o));
    let o = essl(&["lint", "--deny", "warnings", "w.vert"], dir.path());
    assert_eq!(o.status.code(), Some(1));
    assert!(stdout(&o).contains("(warnings denied)"), "{}", stdout(&o));
}

/// A WebGL 1 program as tutorials write it: GLSL ES 1.00, the derivatives extension.
const ES100_VERT: &str = "attribute vec4 a_position;\nvarying vec2 v_uv;\nvoid main() {\n    v_uv = a_position.xy;\n    gl_Position = a_position;\n}\n";
const ES100_FRAG: &str = "#extension GL_OES_standard_derivatives : enable\nprecision mediump float;\nvarying vec2 v_uv;\nvoid main() {\n    float edge = fwidth(v_uv.x);\n    gl_FragColor = vec4(pow(v_uv.x - 0.5, 2.2), edge, 0.0, 1.0);\n}\n";

#[test]
fn targets_decide_the_language_and_the_extensions() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("p.vert"), ES100_VERT).unwrap();
    std::fs::write(dir.path().join("p.frag"), ES100_FRAG).unwrap();
    std::fs::write(dir.path().join("g.vert"), GOOD_VERT).unwrap();
    // WebGL 1: the program links, and the numerical lints run on GLSL ES 1.00.
    let o = essl(
        &[
            "lint", "--target", "webgl1", "--format", "json", "p.vert", "p.frag",
        ],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    let lines: Vec<serde_json::Value> = stdout(&o)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert!(lines.iter().all(|l| l["target"] == "webgl1"), "{lines:?}");
    let frag = lines.iter().find(|l| l["file"] == "p.frag").unwrap();
    assert_eq!(frag["version"], "100");
    let codes: Vec<&str> = frag["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| d["code"].as_str().unwrap())
        .collect();
    assert_eq!(codes, ["pow-negative-base"]);
    assert_eq!(lines[2]["kind"], "program");
    assert_eq!(lines[2]["ok"], true);
    // WebGL 2 offers the extension to no GLSL ES 1.00 shader.
    let o = essl(&["lint", "--color", "never", "p.frag"], dir.path());
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    assert!(
        stdout(&o).contains("error[extension-required]"),
        "{}",
        stdout(&o)
    );
    // WebGL 1 compiles no `#version 300 es`.
    let o = essl(
        &["lint", "--color", "never", "--target", "webgl1", "g.vert"],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    assert!(
        stdout(&o).contains("error[unsupported-version]"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn defines_reach_the_preprocessor() {
    let dir = tempfile::tempdir().unwrap();
    let text = GOOD_VERT.replace(
        "gl_Position = a_position;",
        "gl_Position = a_position * SCALE;",
    );
    std::fs::write(dir.path().join("d.vert"), text).unwrap();
    assert_eq!(essl(&["lint", "d.vert"], dir.path()).status.code(), Some(1));
    assert_eq!(
        essl(&["lint", "-D", "SCALE=2.0", "d.vert"], dir.path())
            .status
            .code(),
        Some(0)
    );
    assert_eq!(
        essl(&["lint", "-DSCALE=2.0", "d.vert"], dir.path())
            .status
            .code(),
        Some(0)
    );
}

#[test]
fn folders_recurse_and_pairs_link() {
    let dir = tempfile::tempdir().unwrap();
    let sub = dir.path().join("a/b");
    std::fs::create_dir_all(&sub).unwrap();
    std::fs::write(sub.join("p.vert"), GOOD_VERT).unwrap();
    std::fs::write(sub.join("p.frag"), GOOD_FRAG).unwrap();
    std::fs::write(sub.join("p.fixed.vert"), GOOD_VERT).unwrap();
    std::fs::write(
        sub.join("p.fixed.frag"),
        GOOD_FRAG.replace("u_color", "u_colour"),
    )
    .unwrap();
    // A varying the vertex shader does not write: a link error.
    std::fs::write(sub.join("q.vert"), GOOD_VERT).unwrap();
    std::fs::write(
        sub.join("q.frag"),
        GOOD_FRAG
            .replace("uniform vec4 u_color;", "in vec4 v_color;")
            .replace("u_color", "v_color"),
    )
    .unwrap();
    std::fs::write(dir.path().join("README.md"), "not a shader").unwrap();
    let o = essl(&["lint", "--color", "never", "."], dir.path());
    let out = stdout(&o);
    assert_eq!(o.status.code(), Some(1), "{out}");
    assert!(
        out.contains("linked `a/b/p.fixed.vert` + `a/b/p.fixed.frag`"),
        "{out}"
    );
    assert!(out.contains("linked `a/b/p.vert` + `a/b/p.frag`"), "{out}");
    assert!(
        out.contains("error: program `a/b/q.vert` + `a/b/q.frag` does not link"),
        "{out}"
    );
    assert!(
        out.contains("--> a/b/q.frag:"),
        "link errors point into the fragment shader: {out}"
    );
    assert!(out.contains("info log (getProgramInfoLog):"), "{out}");
    assert!(
        out.trim_end()
            .ends_with("6 files, 1 error, 0 warnings, 3 programs linked"),
        "{out}"
    );
    let o = essl(&["lint", "--no-link", "."], dir.path());
    assert_eq!(o.status.code(), Some(0));
}

#[test]
fn json_lines_shape() {
    let o = essl(&["lint", "--format", "json", "shaders-glsl"], &repo_root());
    assert_eq!(o.status.code(), Some(1));
    let lines: Vec<serde_json::Value> = stdout(&o)
        .lines()
        .map(|l| serde_json::from_str(l).expect("each line is JSON"))
        .collect();
    let shaders: Vec<_> = lines.iter().filter(|v| v["kind"] == "shader").collect();
    let programs: Vec<_> = lines.iter().filter(|v| v["kind"] == "program").collect();
    // One object per shader file and one per NAME.vert + NAME.frag pair in the folder.
    let names: Vec<String> = std::fs::read_dir(repo_root().join("shaders-glsl"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".vert") || n.ends_with(".frag"))
        .collect();
    let pairs = names
        .iter()
        .filter(|n| n.ends_with(".vert") && names.contains(&n.replace(".vert", ".frag")))
        .count();
    assert_eq!(shaders.len(), names.len());
    assert_eq!(programs.len(), pairs);
    assert!(pairs >= 18, "the seeds give at least 18 pairs");
    assert_eq!(lines.last().unwrap()["kind"], "summary");
    for s in &shaders {
        assert!(s["file"].as_str().unwrap().starts_with("shaders-glsl/"));
        assert!(s["stage"] == "vertex" || s["stage"] == "fragment");
        assert!(s["ok"].is_boolean());
        for d in s["diagnostics"].as_array().unwrap() {
            assert!(d["severity"] == "error" || d["severity"] == "warning");
            for key in ["line", "column", "end_line", "end_column"] {
                assert!(d[key].as_u64().unwrap() >= 1, "{key} is 1-based: {d}");
            }
            assert!(d["code"].is_string() && d["message"].is_string());
            assert!(d["help"].is_string() || d["help"].is_null());
            if let Some(fix) = d.get("fix") {
                assert!(fix["applicability"] == "certain" || fix["applicability"] == "suggested");
                for e in fix["edits"].as_array().unwrap() {
                    assert!(e["line"].as_u64().unwrap() >= 1 && e["replacement"].is_string());
                }
            }
        }
    }
    let nbsp = shaders
        .iter()
        .find(|s| s["file"] == "shaders-glsl/spot-smooth-nbsp.frag")
        .unwrap();
    assert_eq!(nbsp["ok"], false);
    let semi = nbsp["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .find(|d| d["code"] == "missing-semicolon")
        .unwrap();
    assert_eq!(
        (semi["line"].as_u64(), semi["column"].as_u64()),
        (Some(19), Some(27))
    );
    for p in &programs {
        assert!(p["vertex"].as_str().unwrap().ends_with(".vert"));
        assert!(p["fragment"].as_str().unwrap().ends_with(".frag"));
        assert!(p["ok"].is_boolean() && p["log"].is_string());
        for u in p["uniforms"].as_array().unwrap() {
            assert!(
                u["name"].is_string() && u["type"].is_string() && u["size"].as_u64().unwrap() >= 1
            );
        }
        for a in p["attributes"].as_array().unwrap() {
            assert!(a["name"].is_string() && a["type"].is_string() && a["location"].is_i64());
        }
    }
    let step = programs
        .iter()
        .find(|p| p["vertex"] == "shaders-glsl/spot-step.vert")
        .unwrap();
    assert_eq!(step["ok"], true);
    assert!(step["uniforms"]
        .as_array()
        .unwrap()
        .iter()
        .any(|u| u["name"] == "u_limit" && u["type"] == "FLOAT"));
    let broken = programs
        .iter()
        .find(|p| p["vertex"] == "shaders-glsl/spot-smooth-nbsp.vert")
        .unwrap();
    assert_eq!(broken["ok"], false);
    assert_eq!(broken["log"], "Fragment shader is not compiled.\n");
}

#[test]
fn fix_repairs_the_seed_shader() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("spot.frag");
    std::fs::copy(
        repo_root().join("shaders-glsl/spot-smooth-nbsp.frag"),
        &path,
    )
    .unwrap();
    let o = essl(
        &["lint", "--fix", "--color", "never", "spot.frag"],
        dir.path(),
    );
    let out = stdout(&o);
    assert_eq!(
        o.status.code(),
        Some(0),
        "no error remains after --fix: {out}"
    );
    assert!(out.contains("fixed `spot.frag`: "), "{out}");
    let fixed = std::fs::read_to_string(&path).unwrap();
    assert!(fixed.contains("uniform float u_innerLimit;\n"));
    assert!(fixed.contains("-u_lightDirection);\n"));
    assert!(!fixed
        .lines()
        .any(|l| !l.trim_start().starts_with("//") && l.contains('\u{a0}')));
    // No temporary file is left behind.
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    // Linting again: no error, nothing left to fix.
    let o = essl(
        &["lint", "--fix", "--format", "json", "spot.frag"],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(0));
    let first: serde_json::Value =
        serde_json::from_str(stdout(&o).lines().next().unwrap()).unwrap();
    assert_eq!(first["ok"], true);
    assert_eq!(first["fixes_applied"], 0);
}

const HAZARD_FRAG: &str = "#version 300 es\nprecision highp float;\nuniform vec3 u_a;\nuniform vec3 u_b;\nin vec3 v_n;\nout vec4 color;\nvoid main() {\n    float d = dot(normalize(v_n), normalize(u_a));\n    color = vec4(acos(d), pow(d, 2.5), 0.0, 1.0);\n}\n";

#[test]
fn lints_warn_by_default_and_rules_can_be_allowed_or_denied() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("h.frag"), HAZARD_FRAG).unwrap();
    let o = essl(&["lint", "--color", "never", "h.frag"], dir.path());
    let out = stdout(&o);
    assert_eq!(o.status.code(), Some(0), "{out}");
    assert!(
        out.contains("warning[acos-domain]") && out.contains("warning[pow-negative-base]"),
        "{out}"
    );
    // Allowed: not reported.
    let o = essl(
        &[
            "lint",
            "--color",
            "never",
            "--allow",
            "acos-domain",
            "h.frag",
        ],
        dir.path(),
    );
    assert!(!stdout(&o).contains("acos-domain"));
    // Denied: an error, exit 1; a later --allow wins over an earlier --deny.
    let o = essl(
        &[
            "lint",
            "--color",
            "never",
            "--deny",
            "pow-negative-base",
            "h.frag",
        ],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(1));
    assert!(stdout(&o).contains("error[pow-negative-base]"));
    let o = essl(
        &[
            "lint", "--color", "never", "--deny", "all", "--allow", "all", "h.frag",
        ],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(0));
    assert!(!stdout(&o).contains("warning["));
    // --deny warnings fails on the default warnings.
    let o = essl(
        &["lint", "--color", "never", "--deny", "warnings", "h.frag"],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(1));
    // An unknown rule is a usage error naming the known ones.
    let o = essl(&["lint", "--deny", "no-such-rule", "h.frag"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("unknown lint rule `no-such-rule`"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn an_essl_allow_comment_silences_one_finding() {
    let dir = tempfile::tempdir().unwrap();
    let src = HAZARD_FRAG.replace(
        "    color = vec4(acos(d)",
        "    // essl-allow: acos-domain\n    color = vec4(acos(d)",
    );
    std::fs::write(dir.path().join("h.frag"), src).unwrap();
    let out = stdout(&essl(&["lint", "--color", "never", "h.frag"], dir.path()));
    assert!(
        !out.contains("acos-domain") && out.contains("pow-negative-base"),
        "{out}"
    );
}

#[test]
fn sarif_output_is_one_log_with_rules_and_results() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("h.frag"), HAZARD_FRAG).unwrap();
    std::fs::write(
        dir.path().join("bad.vert"),
        "#version 300 es\nvoid main() { gl_Position = vec4(1) }\n",
    )
    .unwrap();
    let o = essl(&["lint", "--format", "sarif", "."], dir.path());
    assert_eq!(o.status.code(), Some(1));
    let log: serde_json::Value = serde_json::from_str(&stdout(&o)).expect("one JSON document");
    assert_eq!(log["version"], "2.1.0");
    let results = log["runs"][0]["results"].as_array().unwrap();
    let ids: Vec<&str> = results
        .iter()
        .map(|r| r["ruleId"].as_str().unwrap())
        .collect();
    assert!(
        ids.contains(&"acos-domain") && ids.contains(&"missing-semicolon"),
        "{ids:?}"
    );
    let rules = log["runs"][0]["tool"]["driver"]["rules"]
        .as_array()
        .unwrap();
    assert!(rules.iter().any(|r| r["id"] == "pow-negative-base"));
}

#[test]
fn rules_subcommand_lists_and_documents_rules() {
    let dir = tempfile::tempdir().unwrap();
    let o = essl(&["rules"], dir.path());
    assert!(stdout(&o)
        .lines()
        .any(|l| l.starts_with("smoothstep-edges")));
    let o = essl(&["rules", "acos-domain"], dir.path());
    assert!(stdout(&o).contains("## What it does"), "{}", stdout(&o));
    assert_eq!(essl(&["rules", "nope"], dir.path()).status.code(), Some(2));
}

#[cfg(feature = "render")]
#[test]
fn render_writes_the_png_and_a_json_line() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("bad.json"), "{\"width\": 0}").unwrap();
    let o = essl(&["render", "bad.json", "-o", "x.png"], dir.path());
    assert_eq!(
        o.status.code(),
        Some(2),
        "a malformed scene is a usage error"
    );
    let Some(scenes) = essl_testdata::scenes() else {
        return;
    };
    let scene = scenes.join("spot-smooth.json");
    let png = dir.path().join("spot.png");
    let o = Command::new(env!("CARGO_BIN_EXE_essl"))
        .args([
            "render",
            scene.to_str().unwrap(),
            "-o",
            png.to_str().unwrap(),
            "--times",
            "3",
        ])
        .env("XDG_RUNTIME_DIR", dir.path())
        .output()
        .unwrap();
    if o.status.code() == Some(2) && stderr(&o).contains("adapter") {
        essl_testdata::adapter_missing(&stderr(&o));
        return;
    }
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let line: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(line["triangles"], 8192);
    assert_eq!(line["width"], 256);
    assert!(line["ms_per_frame"].as_f64().unwrap() > 0.0);
    let image = essl_scene::read_png(&png).unwrap();
    let reference = essl_scene::read_png(&scenes.join("reference/spot-smooth.png")).unwrap();
    let diff = essl_scene::compare(&image, &reference, 3).unwrap();
    assert!(
        diff.within_tolerance as f64 >= 0.999 * diff.pixels as f64,
        "{diff:?}"
    );
}

/// A fragment shader whose only lint finding is a note: reversed constant `smoothstep` edges.
const NOTE_FRAG: &str = "#version 300 es\nprecision highp float;\nin float v_d;\nout vec4 color;\nvoid main() {\n    color = vec4(smoothstep(0.25, 0.24, v_d));\n}\n";

#[test]
fn notes_are_counted_hidden_and_shown_with_show_notes() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("n.frag"), NOTE_FRAG).unwrap();
    let o = essl(&["lint", "--color", "never", "n.frag"], dir.path());
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(
        stdout(&o),
        "1 file, 0 errors, 0 warnings, 1 note hidden (--show-notes)\n"
    );
    let o = essl(
        &["lint", "--color", "never", "--show-notes", "n.frag"],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(0), "notes never fail a run");
    let out = stdout(&o);
    assert!(out.contains("note[smoothstep-reversed-constant]"), "{out}");
    assert!(
        out.ends_with("1 file, 0 errors, 0 warnings, 1 note\n"),
        "{out}"
    );
    // `--deny warnings` does not count notes; `--warn RULE` makes them warnings.
    let o = essl(&["lint", "--deny", "warnings", "n.frag"], dir.path());
    assert_eq!(o.status.code(), Some(0));
    let o = essl(
        &["lint", "--warn", "smoothstep-reversed-constant", "n.frag"],
        dir.path(),
    );
    assert!(stdout(&o).contains("1 warning"), "{}", stdout(&o));
    // JSON and SARIF carry the severity.
    let o = essl(
        &["lint", "--format", "json", "--show-notes", "n.frag"],
        dir.path(),
    );
    let first: serde_json::Value =
        serde_json::from_str(stdout(&o).lines().next().unwrap()).unwrap();
    assert_eq!(first["diagnostics"][0]["severity"], "note");
    let o = essl(&["lint", "--format", "json", "n.frag"], dir.path());
    let last: serde_json::Value = serde_json::from_str(stdout(&o).lines().last().unwrap()).unwrap();
    assert_eq!(last["notes_hidden"], 1);
    let o = essl(
        &["lint", "--format", "sarif", "--show-notes", "n.frag"],
        dir.path(),
    );
    let log: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(log["runs"][0]["results"][0]["level"], "note");
}

#[test]
fn minify_prints_the_minified_shader_and_refuses_one_with_errors() {
    let dir = tempfile::tempdir().unwrap();
    let text = "#version 300 es\nprecision highp float;\n// the colour\nuniform vec4 u_color;\n\
        out vec4 color;\nvoid main() {\n    vec4 tinted = u_color * 0.5;\n    color = tinted;\n}\n";
    std::fs::write(dir.path().join("a.frag"), text).unwrap();
    let o = essl(&["minify", "a.frag"], dir.path());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(
        stdout(&o),
        "#version 300 es\nprecision highp float;uniform vec4 u_color;out vec4 color;\
         void main(){vec4 a=u_color*.5;color=a;}\n"
    );
    let o = essl(
        &["minify", "a.frag", "--no-rename", "-o", "out.frag"],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = std::fs::read_to_string(dir.path().join("out.frag")).unwrap();
    assert!(out.contains("vec4 tinted=u_color*.5;"), "{out}");
    std::fs::write(
        dir.path().join("b.frag"),
        GOOD_FRAG.replace("u_color;\n}", "u_colour;\n}"),
    )
    .unwrap();
    let o = essl(&["minify", "b.frag"], dir.path());
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stderr(&o).contains("undeclared-identifier"),
        "{}",
        stderr(&o)
    );
    assert!(stdout(&o).is_empty());
}
