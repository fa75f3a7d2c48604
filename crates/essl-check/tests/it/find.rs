//! Naming the shaders: a text's stage from its name, essl.toml or a pragma; hidden and
//! ignored files left out of a walk; one file named twice checked once.

use std::path::Path;

use essl_check::{find, find_text, Configs, FindOptions, Overrides, UsageError};

use crate::write;

#[test]
fn a_texts_stage_from_its_name_its_settings_or_a_pragma() {
    let configs = Configs::new(Overrides::default());
    let stage = |path: &str, text: &str| {
        find_text(Path::new(path), text.to_string(), &configs).map(|f| f.inputs[0].stage.as_str())
    };
    assert_eq!(stage("a.vert.glsl", "").unwrap(), "vertex");
    assert_eq!(
        stage("a.glsl", "#pragma essl stage( fragment )\n").unwrap(),
        "fragment"
    );
    assert!(matches!(
        stage("a.glsl", "gl_Position = p;"),
        Err(UsageError::NoStage(_))
    ));
    let forced = Configs::new(Overrides {
        stage: Some(essl::Stage::Vertex),
        ..Overrides::default()
    });
    let found = find_text(Path::new("a.glsl"), String::new(), &forced).unwrap();
    assert_eq!(found.inputs[0].stage, essl::Stage::Vertex);
}

#[test]
fn a_walk_skips_hidden_and_ignored_files_and_names_a_file_once() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write(
        root,
        &[
            ("a.vert", ""),
            ("b.frag", ""),
            (".hidden.frag", ""),
            ("notes.txt", ""),
            ("sub/c.vs", ""),
            ("gen/d.frag", ""),
            (".gitignore", "gen/\n"),
            ("x.glsl", ""),
        ],
    );
    let configs = Configs::new(Overrides::default());
    let found = find(&[root.to_path_buf()], &FindOptions::new(), &configs).unwrap();
    let names: Vec<String> = found
        .inputs
        .iter()
        .map(|i| i.path.strip_prefix(root).unwrap().display().to_string())
        .collect();
    assert_eq!(names, ["a.vert", "b.frag", "sub/c.vs"]);
    assert_eq!(
        found.errors.len(),
        1,
        "x.glsl has no stage: {:?}",
        found.errors
    );
    let twice = [root.join("a.vert"), root.join("./a.vert")];
    let found = find(&twice, &FindOptions::new(), &configs).unwrap();
    assert_eq!(found.inputs.len(), 1);
}

#[test]
fn a_text_whose_settings_cannot_be_read_is_a_usage_error_not_a_check_of_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let configs = Configs::new(Overrides {
        config: Some(dir.path().join("no-such").join("essl.toml")),
        ..Overrides::default()
    });
    let text =
        "#version 300 es\nprecision mediump float;\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n";
    let checked = essl_check::check_text(
        Path::new("a.frag"),
        text.to_string(),
        &configs,
        &essl_check::Files::disk(),
        essl_check::CheckOptions::default(),
    );
    match checked {
        Err(UsageError::Config(e)) => assert!(e.to_string().contains("no-such"), "{e}"),
        other => panic!("{:?}", other.map(|(u, _)| u.shaders.len())),
    }
}
