//! Shaders kept inside other files: HTML `<script>` tags and JS/TS template literals.
//!
//! Each shader found is an [`Embedded`]: its byte range in the host file (so diagnostics and
//! fixes land on the host's own lines), its stage where the file tells it, and the name the
//! host gives it (a tag's `id`, the variable a literal is assigned to), from which shaders are
//! paired into programs ([`pairs`]). What cannot be checked as written — a template literal
//! with `${…}` interpolations, a shader whose stage nothing tells — is kept with a [`Skip`]
//! reason, so that a run reports it instead of dropping it.
//!
//! - [`html`]: `<script type="x-shader/x-vertex">` / `x-fragment`, `notjs` tags whose id ends in
//!   `vertex-shader` / `fragment-shader`, and the template literals of the page's inline scripts;
//! - [`js`]: template literals that start with `#version` or are tagged `glsl` / `/* glsl */`.

mod html;
mod js;
mod stage;

use std::ops::Range;
use std::path::Path;

use essl::Stage;

pub use stage::stage_pragma;

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
    /// A template literal with `${…}` interpolations: its text is known only when it runs.
    Interpolated,
    /// A template literal with `\` escapes: its text is not what the file shows.
    Escapes,
    /// Nothing tells whether it is a vertex or a fragment shader.
    NoStage,
}

impl Skip {
    /// Why, in words.
    pub fn reason(self) -> &'static str {
        match self {
            Skip::Interpolated => {
                "a template literal with `${…}` interpolations (its text is known only at run time)"
            }
            Skip::Escapes => {
                "a template literal with `\\` escapes (its text differs from the file's)"
            }
            Skip::NoStage => {
                "nothing tells its stage: add `#pragma essl stage(vertex)` or `stage(fragment)`"
            }
        }
    }
}

/// A shader inside a host file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Embedded {
    /// Its text's byte range in the host file.
    pub range: Range<usize>,
    /// Its stage, where the host or the shader tells it.
    pub stage: Option<Stage>,
    /// The name the host gives it: a `<script>`'s `id`, or the variable or property a literal
    /// is assigned to.
    pub name: Option<String>,
    /// Why it is not checked, if it is not.
    pub skip: Option<Skip>,
}

/// The shaders inside `text`, a file of kind `kind`, in the order they appear.
pub fn extract(kind: HostKind, text: &str) -> Vec<Embedded> {
    let mut found = match kind {
        HostKind::Html => html::extract(text),
        HostKind::Script => js::extract(text, 0),
    };
    for e in &mut found {
        if e.skip.is_none() {
            let body = &text[e.range.clone()];
            e.stage = stage_pragma(body).or(e.stage).or_else(|| {
                let by_name = e.name.as_deref().and_then(stage::stage_from_name);
                by_name.or_else(|| stage::stage_from_text(body))
            });
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
    let checked = || (0..found.len()).filter(|&i| found[i].skip.is_none());
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
