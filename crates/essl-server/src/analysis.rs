//! One document checked: compiled and linted with the settings of its nearest `essl.toml`,
//! and indexed; and the program it forms with its `NAME.vert` / `NAME.frag` partner.

use std::path::{Path, PathBuf};

use essl::link::Program;
use essl::source::SourceFile;
use essl::{Shader, Stage};
use essl_build::Config;

use crate::index::Index;

/// A shader checked and indexed.
#[derive(Debug)]
pub struct Analysis {
    /// The compiled shader, lint findings among its diagnostics.
    pub shader: Shader,
    /// What its names refer to.
    pub index: Index,
}

/// The stage of a document: from its extension (also `NAME.vert.glsl`), essl.toml's
/// `[stages]`, a `#pragma essl stage(…)` line, or, last, whether it writes `gl_Position`.
pub fn stage_of(path: &Path, text: &str, config: &Config) -> Stage {
    let from_name = Stage::from_path(path).or_else(|| {
        let stem = Path::new(path.file_stem()?);
        Stage::from_path(stem)
    });
    from_name
        .or_else(|| config.stage_of(path))
        .or_else(|| pragma_stage(text))
        .unwrap_or(if text.contains("gl_Position") {
            Stage::Vertex
        } else {
            Stage::Fragment
        })
}

/// The stage a `#pragma essl stage(vertex|fragment)` line names.
fn pragma_stage(text: &str) -> Option<Stage> {
    text.lines().find_map(|l| {
        let l: String = l.chars().filter(|c| !c.is_whitespace()).collect();
        match l.as_str() {
            "#pragmaesslstage(vertex)" => Some(Stage::Vertex),
            "#pragmaesslstage(fragment)" => Some(Stage::Fragment),
            _ => None,
        }
    })
}

/// Compiles, lints (essl.toml's levels) and indexes `text`, the document at `path`.
pub fn analyse(path: &Path, text: &str, config: &Config) -> Analysis {
    let stage = stage_of(path, text, config);
    let file = SourceFile::new(path.display().to_string(), text);
    let mut shader = essl::compile(file, stage, &config.compile_options());
    let found = essl_lint::lint(&shader, &config.rules);
    if !found.is_empty() {
        shader.diagnostics.extend(found);
        essl::diagnostic::sort(&mut shader.diagnostics);
    }
    let index = Index::build(&shader.module, &shader.file);
    Analysis { shader, index }
}

/// The file the document at `path` is linked with: `NAME.frag` for `NAME.vert` (and the other
/// stage extensions, `.vs`/`.fs`, `.vsh`/`.fsh`, also before `.glsl`).
pub fn partner(path: &Path) -> Option<PathBuf> {
    let name = path.file_name()?.to_str()?;
    let (base, glsl) = match name.strip_suffix(".glsl") {
        Some(b) => (b, ".glsl"),
        None => (name, ""),
    };
    let (stem, ext) = base.rsplit_once('.')?;
    let other = match ext {
        "vert" => "frag",
        "frag" => "vert",
        "vs" => "fs",
        "fs" => "vs",
        "vsh" => "fsh",
        "fsh" => "vsh",
        _ => return None,
    };
    Some(path.with_file_name(format!("{stem}.{other}{glsl}")))
}

/// Links a vertex and a fragment shader when both compiled.
pub fn link(vs: &Shader, fs: &Shader) -> Option<Program> {
    (vs.ok() && fs.ok()).then(|| essl::link::link(vs, fs))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn partners_and_stages() {
        assert_eq!(
            partner(Path::new("/a/l.vert")).unwrap(),
            Path::new("/a/l.frag")
        );
        assert_eq!(
            partner(Path::new("l.fs.glsl")).unwrap(),
            Path::new("l.vs.glsl")
        );
        assert_eq!(partner(Path::new("l.glsl")), None);
        let c = Config::default();
        assert_eq!(
            stage_of(Path::new("a.glsl"), "gl_Position = p;", &c),
            Stage::Vertex
        );
        let pragma = "#pragma essl stage( vertex )\n";
        assert_eq!(stage_of(Path::new("a.glsl"), pragma, &c), Stage::Vertex);
        assert_eq!(stage_of(Path::new("a.frag.glsl"), "", &c), Stage::Fragment);
    }
}
