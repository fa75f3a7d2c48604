//! Shaders kept inside other files: HTML `<script>` tags, and JS/TS literals — template
//! literals, strings, `+` chains and `[…].join('\n')` arrays — as JavaScript computes their
//! value.
//!
//! Each shader found is an [`Embedded`]: its text as [`Piece`]s of the host file (so that
//! diagnostics and fixes land on the host's own lines, through escapes and `${…}`
//! substitutions of constants), its stage where the file tells it, and the name the host gives
//! it (a tag's `id`, the variable a literal is assigned to), from which shaders are paired into
//! programs ([`pairs`]). What cannot be checked as written — a substitution whose value is
//! known only at run time, a shader whose stage nothing tells — is kept with a [`Skip`] reason,
//! so that a run reports it instead of dropping it. A tagged literal with no `main` is a
//! *chunk*: code meant to be put into shaders, checked as a library.
//!
//! - [`html`]: `<script type="x-shader/x-vertex">` / `x-fragment`, `notjs` tags whose id ends in
//!   `vertex-shader` / `fragment-shader`, and the literals of the page's inline scripts;
//! - [`js`]: literals whose value starts with `#version` or that are tagged `glsl` /
//!   `/* glsl */`, with the constants and imports their substitutions name.

mod html;
pub(crate) mod js;
mod stage;

use std::ops::Range;
use std::path::Path;
use std::sync::Arc;

use essl::source::SourceFile;
use essl::Stage;

pub use js::Unknown;
pub use js::{Imports, NoImports};

pub use stage::{chunk_pragma, stage_pragma};

/// What kind of file holds shaders inside it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HostKind {
    /// An HTML page (`.html`, `.htm`, `.xhtml`).
    Html,
    /// JavaScript or TypeScript (`.js`, `.mjs`, `.cjs`, `.jsx`, `.ts`, `.mts`, `.cts`, `.tsx`).
    Script,
}

impl HostKind {
    /// The host kind a file's extension names, if any.
    pub fn of(path: &Path) -> Option<HostKind> {
        match path.extension()?.to_str()?.to_ascii_lowercase().as_str() {
            "html" | "htm" | "xhtml" => Some(HostKind::Html),
            "js" | "mjs" | "cjs" | "jsx" | "ts" | "mts" | "cts" | "tsx" => Some(HostKind::Script),
            _ => None,
        }
    }
}

/// Why an embedded shader is not checked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Skip {
    /// A `${…}` substitution whose value is known only when the script runs (a call, a
    /// variable, an import from a package).
    Interpolated,
    /// An escape sequence JavaScript rejects (an octal escape in a template, a lone
    /// surrogate).
    Escapes,
    /// Nothing tells whether it is a vertex or a fragment shader.
    NoStage,
    /// The script changes the text before it is compiled (`` `…`.replace(…) ``).
    Rewritten,
}

impl Skip {
    /// Why, in words.
    pub fn reason(self) -> &'static str {
        match self {
            Skip::Interpolated => {
                "a `${…}` substitution whose value is known only when the script runs (not a \
                 constant of literals in the file or a file it imports)"
            }
            Skip::Escapes => "an escape sequence that JavaScript rejects in this literal",
            Skip::Rewritten => {
                "the script changes this text before it is compiled (a method such as \
                 `.replace(…)` is called on it)"
            }
            Skip::NoStage => {
                "nothing tells its stage: add `#pragma essl stage(vertex)` or `stage(fragment)`"
            }
        }
    }
}

/// A run of an embedded shader's text and the bytes of its host it comes from.
#[derive(Clone, Debug)]
pub enum Piece {
    /// Host bytes as they are.
    Raw(Range<usize>),
    /// An escape sequence (or a `\r\n` a template reads as `\n`) at `raw`, standing for
    /// `value`.
    Cooked {
        /// The bytes of the escape.
        raw: Range<usize>,
        /// What it stands for.
        value: String,
    },
    /// Text no file holds (the separator of `[…].join(sep)`), placed at byte `at`.
    Added {
        /// The text.
        text: String,
        /// The host byte it is reported at.
        at: usize,
    },
    /// Text from another file (a constant it imports), as pieces of that file.
    From {
        /// The file.
        file: Arc<SourceFile>,
        /// Its pieces.
        pieces: Vec<Piece>,
    },
}

impl PartialEq for Piece {
    fn eq(&self, other: &Piece) -> bool {
        match (self, other) {
            (Piece::Raw(a), Piece::Raw(b)) => a == b,
            (Piece::Cooked { raw: a, value: x }, Piece::Cooked { raw: b, value: y }) => {
                a == b && x == y
            }
            (Piece::Added { text: a, at: x }, Piece::Added { text: b, at: y }) => a == b && x == y,
            (Piece::From { file: a, pieces: x }, Piece::From { file: b, pieces: y }) => {
                Arc::ptr_eq(a, b) && x == y
            }
            _ => false,
        }
    }
}

impl Eq for Piece {}

/// The text `pieces` of `host` stand for.
pub fn text_of(host: &str, pieces: &[Piece]) -> String {
    let mut s = String::new();
    push_text(host, pieces, &mut s);
    s
}

fn push_text(host: &str, pieces: &[Piece], s: &mut String) {
    for p in pieces {
        match p {
            Piece::Raw(r) => s.push_str(&host[r.clone()]),
            Piece::Cooked { value, .. } => s.push_str(value),
            Piece::Added { text, .. } => s.push_str(text),
            Piece::From { file, pieces } => push_text(file.text(), pieces, s),
        }
    }
}

/// A shader inside a host file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Embedded {
    /// The byte range of the host that holds its text (from its first piece to its last).
    pub range: Range<usize>,
    /// Its text, piece by piece.
    pub pieces: Vec<Piece>,
    /// Whether it is a chunk: code to put into shaders (a tagged literal with no `main`),
    /// checked as a library.
    pub chunk: bool,
    /// Where the expression that holds it starts (its backtick, quote or `[`): how presets and
    /// module objects name it.
    pub literal: usize,
    /// Macros the code around it defines for it (a luma.gl module's `defines`), as
    /// `#define NAME VALUE` before a chunk's text.
    pub defines: Vec<(String, String)>,
    /// Its stage, where the host or the shader tells it.
    pub stage: Option<Stage>,
    /// The name the host gives it: a `<script>`'s `id`, or the variable or property a literal
    /// is assigned to.
    pub name: Option<String>,
    /// Why it is not checked, if it is not.
    pub skip: Option<Skip>,
}

/// The shaders inside `text`, a file of kind `kind`, in the order they appear; `imports`
/// follows what the file's substitutions import from other files.
pub fn extract(kind: HostKind, text: &str, imports: &dyn Imports) -> Vec<Embedded> {
    let mut found = match kind {
        HostKind::Html => html::extract(text, imports),
        HostKind::Script => js::extract(text, 0, imports),
    };
    for e in &mut found {
        if e.skip.is_none() {
            let body = text_of(text, &e.pieces);
            let by_text = || {
                let by_name = e.name.as_deref().and_then(stage::stage_from_name);
                by_name.or_else(|| stage::stage_from_text(&body))
            };
            e.stage = stage_pragma(&body).or(e.stage).or_else(by_text);
            if e.stage.is_none() && e.chunk {
                // A library of declarations compiles alike in both stages.
                e.stage = Some(Stage::Vertex);
            }
            if e.stage.is_none() {
                e.skip = Some(Skip::NoStage);
            }
        }
    }
    found
}

/// The programs the file makes plain, as `(vertex, fragment)` indices into `found`: shaders
/// whose names agree once the stage words are taken out (`skyboxVS` + `skyboxFS`,
/// `vertex-shader-3d` + `fragment-shader-3d`), each key naming one shader of each stage; or,
/// when the file holds exactly one vertex and one fragment shader, those two.
pub fn pairs(found: &[Embedded]) -> Vec<(usize, usize)> {
    let checked = || (0..found.len()).filter(|&i| found[i].skip.is_none() && !found[i].chunk);
    let of = |stage: Stage| checked().filter(move |&i| found[i].stage == Some(stage));
    let (vs, fs): (Vec<usize>, Vec<usize>) =
        (of(Stage::Vertex).collect(), of(Stage::Fragment).collect());
    if vs.len() == 1 && fs.len() == 1 {
        return vec![(vs[0], fs[0])];
    }
    // Each key's vertex and fragment shaders, counted: a key pairs when it names exactly one
    // of each. Keys are computed once per shader (a page can hold thousands).
    let mut by_key: std::collections::HashMap<String, [(usize, Option<usize>); 2]> =
        std::collections::HashMap::new();
    for i in checked() {
        let (Some(name), Some(stage)) = (found[i].name.as_deref(), found[i].stage) else {
            continue;
        };
        let slot = &mut by_key.entry(stage::pair_key(name)).or_default()
            [(stage == Stage::Fragment) as usize];
        slot.0 += 1;
        slot.1.get_or_insert(i);
    }
    let mut out: Vec<(usize, usize)> = by_key
        .into_values()
        .filter_map(|[(nv, v), (nf, f)]| (nv == 1 && nf == 1).then_some((v?, f?)))
        .collect();
    out.sort_unstable();
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn e(name: &str, stage: Stage) -> Embedded {
        Embedded {
            range: 0..0,
            pieces: Vec::new(),
            chunk: false,
            literal: 0,
            defines: Vec::new(),
            stage: Some(stage),
            name: Some(name.to_string()),
            skip: None,
        }
    }

    #[test]
    fn pairs_by_name_or_by_being_the_only_two() {
        let only = [e("a", Stage::Vertex), e("b", Stage::Fragment)];
        assert_eq!(pairs(&only), [(0, 1)]);
        let named = [
            e("skyboxVS", Stage::Vertex),
            e("envmapVS", Stage::Vertex),
            e("envmapFS", Stage::Fragment),
            e("skyboxFS", Stage::Fragment),
        ];
        assert_eq!(pairs(&named), [(0, 3), (1, 2)]);
        let ambiguous = [
            e("vs", Stage::Vertex),
            e("fs", Stage::Fragment),
            e("vs", Stage::Vertex),
            e("fs", Stage::Fragment),
        ];
        assert_eq!(pairs(&ambiguous), []);
    }

    #[test]
    fn host_kinds() {
        assert_eq!(HostKind::of(Path::new("a/b.HTML")), Some(HostKind::Html));
        assert_eq!(HostKind::of(Path::new("b.tsx")), Some(HostKind::Script));
        assert_eq!(HostKind::of(Path::new("b.frag")), None);
    }
}
