//! `#include`: off unless asked (GLSL ES has none), followed from the including file's folder
//! and the include folders, with every diagnostic on the file it is in.

use essl_check::{CheckOptions, Overrides};

use crate::{check, lines, write};

const MAIN: &str = "#version 300 es\nprecision highp float;\n#include \"light.glsl\"\nout vec4 c;\nvoid main() { c = vec4(light(1.0)); }\n";

#[test]
fn off_unless_asked() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        &[
            ("a.frag", MAIN),
            ("light.glsl", "float light(float d) { return d; }\n"),
        ],
    );
    // The `.glsl` file has no stage: exclude it, as a project would.
    write(dir.path(), &[("essl.toml", "exclude = [\"*.glsl\"]\n")]);
    let run = check(dir.path(), Overrides::default(), CheckOptions::default());
    assert_eq!(lines(dir.path(), &run)[0], "a.frag:3:1 unknown-directive");
    let on = Overrides {
        includes: true,
        ..Overrides::default()
    };
    let run = check(dir.path(), on, CheckOptions::default());
    assert!(
        lines(dir.path(), &run).is_empty(),
        "{:?}",
        lines(dir.path(), &run)
    );
}

#[test]
fn missing_cyclic_and_errors_inside() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        &[
            ("essl.toml", "include = [\"inc\"]\nexclude = [\"inc/**\"]\n"),
            ("a.frag", &MAIN.replace("light.glsl", "none.glsl")),
            ("b.frag", &MAIN.replace("light.glsl", "loop.glsl")),
            ("c.frag", MAIN),
            ("inc/loop.glsl", "#include \"loop.glsl\"\n"),
            (
                "inc/light.glsl",
                "float light(float d) {\n  return d * undefined_name;\n}\n",
            ),
        ],
    );
    let run = check(dir.path(), Overrides::default(), CheckOptions::default());
    assert_eq!(
        lines(dir.path(), &run),
        [
            "a.frag:3:1 include-not-found",
            "inc/light.glsl:2:14 undeclared-identifier",
            "inc/loop.glsl:1:1 include-cycle",
        ]
    );
    // Each unit says what it includes, so that a build script can ask to be told of changes.
    let c = run
        .results
        .iter()
        .flat_map(|u| &u.shaders)
        .find(|s| s.path.ends_with("c.frag"))
        .unwrap();
    assert_eq!(c.assembly.files().len(), 2);
}
