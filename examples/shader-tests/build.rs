//! Checks the seeds' corrected shaders and generates their bindings, as a project's build script
//! would for its own `shaders/` folder. When the shared data is beside the repository (or named
//! by `ESSL_CORPORA` / `ESSL_SCENES`), also generates bindings for every webgl2fundamentals
//! program that Chromium links and for the programs of the shared scenes: the crate then
//! compiles those too (`cfg(essl_corpus)`, `cfg(essl_scenes)`).

use std::path::{Path, PathBuf};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::var("OUT_DIR")?);
    println!("cargo::rustc-check-cfg=cfg(essl_corpus)");
    println!("cargo::rustc-check-cfg=cfg(essl_scenes)");

    // This crate's own shaders, with the settings of its `essl.toml` (warnings denied).
    let report = essl_build::check("shaders")?;
    report.write_bindings(out.join("shaders.rs"))?;

    // The seeds' shaders that compile: each `*.fixed.*` twin, and the files that need none.
    let report = essl_build::Check::new("../../shaders-glsl")
        .filter(corrected)
        .run()?;
    report.write_bindings(out.join("seeds.rs"))?;

    // Every webgl2fundamentals program Chromium links (pairs from the oracle's record).
    println!("cargo:rerun-if-env-changed=ESSL_CORPORA");
    println!("cargo:rerun-if-changed=../../tests/oracle/webgl2fundamentals.json");
    let corpus =
        essl_testdata::location("ESSL_CORPORA", "corpora").join("webgl2fundamentals_shaders.jsonl");
    if corpus.is_file() {
        println!("cargo:rerun-if-changed={}", corpus.display());
        let dir = out.join("corpus");
        write_corpus_programs(&corpus, &dir)?;
        let report = essl_build::Check::new(&dir).lints(false).run()?;
        report.write_bindings(out.join("corpus.rs"))?;
        println!("cargo:rustc-cfg=essl_corpus");
    }

    // The shared scenes' programs, one per scene, named after the scene.
    println!("cargo:rerun-if-env-changed=ESSL_SCENES");
    let scenes = essl_testdata::location("ESSL_SCENES", "scenes");
    if scenes.is_dir() {
        println!("cargo:rerun-if-changed={}", scenes.display());
        let dir = out.join("scenes");
        write_scene_programs(&scenes, &dir)?;
        let report = essl_build::Check::new(&dir).lints(false).run()?;
        report.write_bindings(out.join("scenes.rs"))?;
        println!("cargo:rustc-cfg=essl_scenes");
    }
    Ok(())
}

/// A `*.fixed.*` file, or one without a `.fixed` twin (a folder: yes).
fn corrected(path: &Path) -> bool {
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
    let Some((stem, ext)) = name.rsplit_once('.') else {
        return true;
    };
    stem.ends_with(".fixed") || !path.with_file_name(format!("{stem}.fixed.{ext}")).exists()
}

/// Writes `pV_F.vert` + `pV_F.frag` for each program of the corpus that Chromium linked.
fn write_corpus_programs(corpus: &Path, dir: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let sources: Vec<serde_json::Value> = std::fs::read_to_string(corpus)?
        .lines()
        .map(serde_json::from_str)
        .collect::<Result<_, _>>()?;
    let oracle: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(
        "../../tests/oracle/webgl2fundamentals.json",
    )?)?;
    let _ = std::fs::remove_dir_all(dir);
    std::fs::create_dir_all(dir)?;
    for p in oracle["programs"].as_array().ok_or("no programs")? {
        if p["ok"] != true {
            continue;
        }
        let (v, f) = (p["vertex"].as_u64(), p["fragment"].as_u64());
        let (Some(v), Some(f)) = (v, f) else {
            return Err("a program without shader indices".into());
        };
        for (i, ext) in [(v, "vert"), (f, "frag")] {
            let text = sources[i as usize]["source"].as_str().ok_or("no source")?;
            std::fs::write(dir.join(format!("p{v}_{f}.{ext}")), text)?;
        }
    }
    Ok(())
}

/// Writes `SCENE.vert` + `SCENE.frag` for each scene file.
fn write_scene_programs(scenes: &Path, dir: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let _ = std::fs::remove_dir_all(dir);
    std::fs::create_dir_all(dir)?;
    for entry in std::fs::read_dir(scenes)? {
        let path = entry?.path();
        if path.extension().is_none_or(|e| e != "json") {
            continue;
        }
        let scene: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&path)?)?;
        let stem = path
            .file_stem()
            .and_then(|s| s.to_str())
            .ok_or("a scene name")?;
        for (key, ext) in [("vertex_shader", "vert"), ("fragment_shader", "frag")] {
            let file = scene[key].as_str().ok_or("a shader name")?;
            std::fs::copy(scenes.join(file), dir.join(format!("{stem}.{ext}")))?;
        }
    }
    Ok(())
}
