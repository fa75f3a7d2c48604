//! The WGSL of the seeds' corrected programs (`shaders-glsl/`), as `essl translate` writes it,
//! with the binding map: snapshots a person reviews for readability (GLSL names kept, the
//! comments where the lowering added something) and that change only on purpose.

use std::path::Path;

use essl::source::SourceFile;
use essl::{CompileOptions, Stage};
use essl_translate::{Options, Target};

fn shader(path: &Path, stage: Stage) -> essl::Shader {
    let text = std::fs::read_to_string(path).expect("the seed reads");
    let name = path.file_name().expect("a file").to_string_lossy();
    essl::compile(
        SourceFile::new(name, text),
        stage,
        &CompileOptions::default(),
    )
}

fn translate(name: &str, options: &Options) -> String {
    let dir = essl_testdata::repo_root().join("shaders-glsl");
    let vs = shader(&dir.join(format!("{name}.vert")), Stage::Vertex);
    let fs = shader(&dir.join(format!("{name}.frag")), Stage::Fragment);
    let t = essl_translate::translate_program(&vs, &fs, options).expect("the seed translates");
    for (stage, code) in [(Stage::Vertex, &t.vertex), (Stage::Fragment, &t.fragment)] {
        if options.target == Target::Wgsl {
            let text = code.as_text().expect("WGSL is text");
            essl_translate::roundtrip::read_wgsl(text, stage).expect("the WGSL reads back");
        }
    }
    let text = |c: &essl_translate::Code| c.as_text().unwrap_or("(binary)").to_owned();
    format!(
        "// ==== {name}.vert\n{}\n// ==== {name}.frag\n{}\n// ==== {name}.bindings.json\n{}\n",
        text(&t.vertex),
        text(&t.fragment),
        t.bindings.to_json()
    )
}

/// Every `NAME.vert` + `NAME.frag` of `shaders-glsl/` whose shaders compile and link: the
/// seeds as the articles ship them where they are correct, and every `.fixed` program.
fn linkable_seed_programs() -> Vec<String> {
    let dir = essl_testdata::repo_root().join("shaders-glsl");
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .expect("shaders-glsl/ lists")
        .filter_map(|e| {
            let path = e.ok()?.path();
            let name = path
                .file_name()?
                .to_str()?
                .strip_suffix(".vert")?
                .to_owned();
            dir.join(format!("{name}.frag")).exists().then_some(name)
        })
        .filter(|name| {
            let vs = shader(&dir.join(format!("{name}.vert")), Stage::Vertex);
            let fs = shader(&dir.join(format!("{name}.frag")), Stage::Fragment);
            vs.ok() && fs.ok() && essl::link::link(&vs, &fs).ok
        })
        .collect();
    names.sort();
    names
}

#[test]
fn seed_programs_in_wgsl() {
    let names = linkable_seed_programs();
    for known in [
        "gouraud-lambert.fixed",
        "phong-positional.fixed",
        "spot-linear",
        "spot-projected-texture.fixed",
        "spot-flashlight-cookie.fixed",
    ] {
        assert!(names.iter().any(|n| n == known), "{known} no longer links");
    }
    for name in &names {
        insta::assert_snapshot!(name.as_str(), translate(name, &Options::default()));
    }
}

#[test]
fn without_the_webgl_conventions() {
    let options = Options {
        depth_remap: false,
        flip_y: false,
        comments: false,
        ..Options::default()
    };
    insta::assert_snapshot!(translate("spot-flashlight-cookie.fixed", &options));
}

#[test]
fn desktop_glsl_keeps_opengl_conventions() {
    let text = translate("phong-positional.fixed", &Options::new(Target::Glsl));
    assert!(text.contains("#version 450 core"), "{text}");
    assert!(!text.contains("clip_position_depth_0_to_w"), "{text}");
    insta::assert_snapshot!(text);
}

#[test]
fn a_seed_program_as_one_module() {
    let dir = essl_testdata::repo_root().join("shaders-glsl");
    let name = "spot-flashlight-cookie.fixed";
    let vs = shader(&dir.join(format!("{name}.vert")), Stage::Vertex);
    let fs = shader(&dir.join(format!("{name}.frag")), Stage::Fragment);
    let options = Options::default();
    let one = essl_translate::translate_program_module(&vs, &fs, &options).expect("one module");
    let text = one.code.as_text().expect("WGSL is text");
    let (module, _) =
        essl_translate::roundtrip::read_wgsl(text, Stage::Vertex).expect("reads back");
    let names: Vec<_> = module
        .entry_points
        .iter()
        .map(|e| e.name.as_str())
        .collect();
    assert_eq!(names, ["vs_main", "fs_main"]);
    // The binding map is the per-stage translation's.
    let stages = essl_translate::translate_program(&vs, &fs, &options).expect("translates");
    assert_eq!(one.bindings, stages.bindings);
    assert_eq!(text.matches("struct Uniforms {").count(), 1, "{text}");
    insta::assert_snapshot!(text);
}

/// Every seed program becomes one module that naga reads back (a fragment function that
/// calls another is copied after its callee).
#[test]
fn every_seed_program_as_one_module() {
    let dir = essl_testdata::repo_root().join("shaders-glsl");
    for name in linkable_seed_programs() {
        let vs = shader(&dir.join(format!("{name}.vert")), Stage::Vertex);
        let fs = shader(&dir.join(format!("{name}.frag")), Stage::Fragment);
        let one = essl_translate::translate_program_module(&vs, &fs, &Options::default())
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let text = one.code.as_text().expect("WGSL is text");
        assert!(
            !text.contains("Written by naga's WGSL writer"),
            "{name}\n{text}"
        );
        essl_translate::roundtrip::read_wgsl(text, Stage::Vertex)
            .unwrap_or_else(|e| panic!("{name}: {e}\n{text}"));
    }
}

#[test]
fn uniforms_at_module_scope() {
    let options = Options {
        uniforms: essl_translate::Uniforms::ModuleScope,
        ..Options::default()
    };
    let text = translate("phong-positional.fixed", &options);
    assert!(
        text.contains("let uModelViewMatrix = uniforms.uModelViewMatrix;"),
        "{text}"
    );
    insta::assert_snapshot!(text);
}

/// GLSL names in the targets naga's writers write: `u_light0` stays `u_light0` (their namer
/// writes `u_light0_`), where the target does not reserve the name.
#[test]
fn glsl_names_in_every_target() {
    let vs = essl::compile(
        SourceFile::new("names.vert", "#version 300 es\nin vec4 a_pos0;\nout vec2 v_uv0;\nvoid main() { v_uv0 = a_pos0.xy; gl_Position = a_pos0; }\n"),
        Stage::Vertex,
        &CompileOptions::default(),
    );
    let fs = essl::compile(
        SourceFile::new(
            "names.frag",
            "#version 300 es\nprecision highp float;\nin vec2 v_uv0;\nuniform vec4 u_light0;\nout vec4 color;\nvoid main() { vec4 float2 = u_light0; color = float2 * v_uv0.x; }\n",
        ),
        Stage::Fragment,
        &CompileOptions::default(),
    );
    for target in [Target::Msl, Target::Hlsl, Target::Glsl, Target::Wgsl] {
        let t =
            essl_translate::translate_program(&vs, &fs, &Options::new(target)).expect("translates");
        let text = format!(
            "{}\n{}",
            t.vertex.as_text().unwrap(),
            t.fragment.as_text().unwrap()
        );
        let words: Vec<&str> = text
            .split(|c: char| !c.is_ascii_alphanumeric() && c != '_')
            .collect();
        for name in ["v_uv0", "u_light0"] {
            let renamed = format!("{name}_");
            assert!(words.contains(&name), "{}: {name}\n{text}", target.name());
            assert!(
                !words.contains(&renamed.as_str()),
                "{}: {renamed}\n{text}",
                target.name()
            );
        }
        // `float2` is a type in MSL and HLSL: the namer's `float2_` stays there.
        if matches!(target, Target::Msl | Target::Hlsl) {
            assert!(words.contains(&"float2_"), "{}\n{text}", target.name());
        }
    }
}
