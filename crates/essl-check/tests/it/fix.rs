//! `--fix` through the pipeline: rounds on a shader's own file, fixes in an included file
//! applied once for every shader that includes it, and a host file fixed as a whole.

use essl_check::{CheckOptions, FixMode, Overrides};

use crate::{check, lines, write};

fn fixing() -> CheckOptions {
    CheckOptions {
        fix: FixMode::Certain,
        ..CheckOptions::default()
    }
}

#[test]
fn missing_semicolons_are_fixed_in_rounds() {
    let dir = tempfile::tempdir().unwrap();
    let text = "#version 300 es\nprecision highp float;\nuniform float a\nuniform float b\nout vec4 c;\nvoid main() { c = vec4(a + b); }\n";
    write(dir.path(), &[("t.frag", text)]);
    let run = check(dir.path(), Overrides::default(), fixing());
    let unit = &run.results[0];
    assert!(unit.shaders[0].ok(), "{:?}", lines(dir.path(), &run));
    let fixed = &unit.fixed[0];
    assert!(fixed.applied >= 2);
    assert!(fixed.after.contains("uniform float a;\nuniform float b;\n"));
    assert_eq!(fixed.before.text(), text);
    // Nothing is written: writing is the caller's.
    assert_eq!(
        std::fs::read_to_string(dir.path().join("t.frag")).unwrap(),
        text
    );
}

#[test]
fn a_fix_in_an_included_file_is_applied_once_and_its_includers_checked_again() {
    let dir = tempfile::tempdir().unwrap();
    let shader = |name: &str| {
        format!(
            "#version 300 es\nprecision highp float;\n#include \"light.glsl\"\nout vec4 {name};\nvoid main() {{ {name} = vec4(light(1.0)); }}\n"
        )
    };
    write(
        dir.path(),
        &[
            ("essl.toml", "include = [\"common\"]\n"),
            (
                "common/light.glsl",
                "float light(float d) {\n    return d * 0.5\n}\n",
            ),
            ("a.frag", &shader("a")),
            ("b.frag", &shader("b")),
        ],
    );
    let report = check(dir.path(), Overrides::default(), CheckOptions::default());
    let found = lines(dir.path(), &report);
    assert_eq!(
        found,
        [
            "common/light.glsl:2:19 missing-semicolon",
            "common/light.glsl:2:19 missing-semicolon",
            "common/light.glsl:2:19 missing-semicolon"
        ],
        "each shader that includes the file reports it there, and so does the file, a chunk"
    );
    let run = check(dir.path(), Overrides::default(), fixing());
    // The chunk fixes its own file; the shaders that include it are checked again on the
    // fixed text, and propose nothing more.
    assert!(run.fixed_includes.is_empty(), "{:?}", run.fixed_includes);
    let fixed: Vec<_> = run.results.iter().flat_map(|u| &u.fixed).collect();
    assert_eq!(fixed.len(), 1);
    assert!(fixed[0].path.ends_with("common/light.glsl"));
    assert_eq!(fixed[0].applied, 1);
    assert_eq!(
        fixed[0].after,
        "float light(float d) {\n    return d * 0.5;\n}\n"
    );
    assert!(
        lines(dir.path(), &run).is_empty(),
        "the includers checked again"
    );
    // Where the included file is not a unit of the run, the fix is the run's, made once.
    write(
        dir.path(),
        &[(
            "essl.toml",
            "include = [\"common\"]\nexclude = [\"common/**\"]\n",
        )],
    );
    let run = check(dir.path(), Overrides::default(), fixing());
    assert_eq!(run.fixed_includes.len(), 1);
    let fixed = &run.fixed_includes[0];
    assert!(fixed.path.ends_with("common/light.glsl"));
    assert_eq!(
        fixed.applied, 1,
        "one fix, however many shaders proposed it"
    );
    assert_eq!(
        fixed.after,
        "float light(float d) {\n    return d * 0.5;\n}\n"
    );
    assert!(
        lines(dir.path(), &run).is_empty(),
        "the includers checked again"
    );
}

#[test]
fn a_shader_that_includes_is_fixed_in_its_own_file() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        &[
            ("common/light.glsl", "float light(float d) { return d * 0.5; }\n"),
            (
                "a.frag",
                "#version 300 es\nprecision highp float;\n#include \"light.glsl\"\nout vec4 c;\nvoid main() { c = vec4(light(1.0)) }\n",
            ),
        ],
    );
    let overrides = Overrides {
        include_dirs: vec![dir.path().join("common")],
        ..Overrides::default()
    };
    let run = check(dir.path(), overrides, fixing());
    let unit = &run.results[0];
    assert_eq!(unit.fixed.len(), 1);
    assert!(unit.fixed[0].after.contains("c = vec4(light(1.0)); }"));
    assert!(unit.shaders[0].ok());
}

#[test]
fn a_host_file_is_fixed_as_a_whole() {
    let dir = tempfile::tempdir().unwrap();
    let page = "<script id=\"vs\" type=\"x-shader/x-vertex\">#version 300 es\nin vec4 p;\nvoid main() { gl_Position = p }\n</script>\n\
                <script id=\"fs\" type=\"x-shader/x-fragment\">#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() { c = vec4(1) }\n</script>\n";
    write(dir.path(), &[("page.html", page)]);
    let run = check(dir.path(), Overrides::default(), fixing());
    let unit = &run.results[0];
    assert_eq!(unit.fixed.len(), 1);
    assert_eq!(unit.fixed[0].applied, 2);
    assert_eq!(
        unit.fixed[0].after,
        page.replace("= p }", "= p; }")
            .replace("vec4(1) }", "vec4(1); }")
    );
    assert_eq!(unit.programs.len(), 1);
    assert!(unit.programs[0].program.as_ref().unwrap().ok);
}
