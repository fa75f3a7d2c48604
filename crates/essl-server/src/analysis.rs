//! One shader checked: the front end, then lowering and the lints with the settings of its
//! nearest `essl.toml`, and indexed when a request needs it; and the program it forms with its
//! `NAME.vert` / `NAME.frag` partner.

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use essl::diagnostic::Diagnostic;
use essl::link::Program;
use essl::source::{SourceFile, Span};
use essl::{Shader, Stage};
use essl_build::Config;

use crate::index::Index;

/// A shader checked, with its lint findings once they have run, and indexed on first use.
#[derive(Debug)]
pub struct Analysis {
    /// The compiled shader; its diagnostics are the front end's.
    pub shader: Shader,
    /// The lint findings: those of this text once [`Analysis::lint`] ran, until then those of
    /// the previous text that lie outside the edit ([`Analysis::carry_lints`]).
    pub lints: Vec<Diagnostic>,
    /// Whether `lints` are this text's own.
    pub linted: bool,
    /// What its names refer to, built when a request first asks.
    index: OnceLock<Index>,
}

impl Analysis {
    /// Runs the front end on `text`, the document at `path`, with the settings of `config`;
    /// lowering and the lints are left for [`Analysis::lint`].
    pub fn check(path: &Path, text: &str, config: &Config) -> Analysis {
        Analysis::check_as(path, text, stage_of(path, text, config), config)
    }

    /// [`Analysis::check`] for a shader whose stage is known (one inside an HTML or JS file).
    pub fn check_as(path: &Path, text: &str, stage: Stage, config: &Config) -> Analysis {
        let file = SourceFile::new(path.display().to_string(), text);
        let shader = essl::compile_front_end(file, stage, &config.compile_options());
        // A shader with errors is neither lowered nor linted: nothing is left to run.
        let linted = !shader.ok();
        Analysis {
            shader,
            lints: Vec::new(),
            linted,
            index: OnceLock::new(),
        }
    }

    /// Compiles and lints: [`Analysis::check`] and [`Analysis::lint`].
    pub fn analyse(path: &Path, text: &str, config: &Config) -> Analysis {
        let mut a = Analysis::check(path, text, config);
        a.lint(&config.rules);
        a
    }

    /// Lowers the shader to naga IR (naga's validation may add an error) and runs the lints
    /// (with essl.toml's levels), replacing any carried findings.
    pub fn lint(&mut self, rules: &essl_lint::LintOptions) {
        self.shader.lower();
        self.lints = if self.shader.ok() {
            essl_lint::lint(&self.shader, rules)
        } else {
            Vec::new()
        };
        self.linted = true;
    }

    /// Until the lints run on the new text, keeps the findings of `old` (the previous text of
    /// the same document) whose spans all lie in the text the edit left alone, moved by the
    /// edit's change in length, so that an editor's warnings do not blink off and on at each
    /// keystroke.
    pub fn carry_lints(&mut self, old: &Analysis) {
        if self.linted {
            return;
        }
        let (a, b) = (old.shader.file.text(), self.shader.file.text());
        let prefix = a.bytes().zip(b.bytes()).take_while(|(x, y)| x == y).count();
        let most = a.len().min(b.len()) - prefix;
        let suffix = a
            .bytes()
            .rev()
            .zip(b.bytes().rev())
            .take(most)
            .take_while(|(x, y)| x == y)
            .count();
        let moved = |s: Span| -> Option<Span> {
            if s.end as usize <= prefix {
                Some(s)
            } else if s.start as usize >= a.len() - suffix {
                let shift = |x: u32| (x as usize + b.len() - a.len()) as u32;
                Some(Span::new(shift(s.start), shift(s.end)))
            } else {
                None
            }
        };
        self.lints = old
            .lints
            .iter()
            .filter_map(|d| move_diagnostic(d, &moved))
            .collect();
    }

    /// The front end's diagnostics and the lint findings, in source order.
    pub fn diagnostics(&self) -> Vec<&Diagnostic> {
        let mut all: Vec<&Diagnostic> = self.shader.diagnostics.iter().chain(&self.lints).collect();
        all.sort_by(|a, b| essl::diagnostic::order(a, b));
        all
    }

    /// What the shader's names refer to.
    pub fn index(&self) -> &Index {
        self.index
            .get_or_init(|| Index::build(&self.shader.module, &self.shader.file))
    }
}

/// `d` with every span moved by `moved`, or `None` when one of them cannot be.
fn move_diagnostic(d: &Diagnostic, moved: &impl Fn(Span) -> Option<Span>) -> Option<Diagnostic> {
    let mut d = d.clone();
    for s in d.spans_mut() {
        *s = moved(*s)?;
    }
    Some(d)
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
