//! Presets: checking shaders as a library assembles them before WebGL sees them.
//!
//! - `luma` (luma.gl and deck.gl): a program object in the project's code — `{vs, fs,
//!   modules}` given to a deck.gl layer's `super.getShaders` or to luma.gl's `Model` — is
//!   assembled by the luma.gl the project has installed (run in Node.js, [`node`]), with the
//!   modules it names (from their packages, or as the project writes them, [`programs`]), and
//!   checked as WebGL will compile it; every position inside the author's shader is reported
//!   in the author's file, and code luma.gl adds is reported at the shader's start, named.
//!   A `#version` shader that no program object claims is assembled with no modules (luma.gl's
//!   prologue still applies).
//!
//! A preset reads the library from the project's `node_modules`, never from a copy inside
//! essl: what is checked is what the project ships.

mod luma;
mod node;
pub(crate) mod programs;
mod resolve;
mod three;

use std::collections::{HashMap, HashSet};
use std::path::{Path, PathBuf};
use std::sync::Arc;

use essl::source::Span;

use crate::assembly::Assembly;
use crate::check::from_pieces;
use crate::extract::HostKind;
use crate::find::{Found, Host};
use crate::settings::Configs;
use programs::Literal;

/// Prepares every preset the hosts of `found` name.
pub fn prepare(found: &Found, configs: &Configs) -> Prepared {
    let mut prepared = luma::prepare(found, configs);
    three::prepare(found, configs, &mut prepared);
    prepared
}

/// Prepares the presets for the shaders of one text (an editor's document, a bundler's
/// module): the program objects that name its shaders may lie in the scripts beside it (a
/// deck.gl layer's `scatterplot-layer.ts` beside `scatterplot-layer-vertex.glsl.ts`), so those
/// are read too, and each program that holds one of the text's shaders is checked with it.
pub(crate) fn prepare_alone(found: &Found, configs: &Configs) -> Prepared {
    let Some(host) = found.hosts.first() else {
        return Prepared::default();
    };
    let preset = configs.for_file(&host.path).ok().and_then(|s| s.preset);
    if preset.is_none() || host.kind != HostKind::Script {
        return prepare(found, configs);
    }
    let dir = match host.path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let own = key(&host.path);
    let mut all = Found {
        hosts: vec![host.clone()],
        ..Found::default()
    };
    for entry in std::fs::read_dir(dir).into_iter().flatten().flatten() {
        let path = entry.path();
        if HostKind::of(&path) != Some(HostKind::Script) || key(&path) == own {
            continue;
        }
        if let Ok(text) = crate::read::read_source(&path) {
            all.hosts
                .push(Arc::new(Host::new(path, HostKind::Script, text, false)));
        }
    }
    let mut prepared = prepare(&all, configs);
    // The programs that hold one of the text's shaders are the text's to check.
    let mut mine = Vec::new();
    for programs in std::mem::take(&mut prepared.programs).into_values() {
        mine.extend(programs.into_iter().filter(|p| {
            [&p.vs, &p.fs]
                .into_iter()
                .flatten()
                .any(|w| Arc::ptr_eq(&w.literal.file, &host.file))
        }));
    }
    if !mine.is_empty() {
        prepared.programs.insert(own, mine);
    }
    prepared
}

/// A library whose way of assembling shaders a check follows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Preset {
    /// luma.gl's shader assembler, and deck.gl's layers on it.
    Luma,
    /// three.js's `ShaderMaterial` and `RawShaderMaterial`.
    Three,
}

impl Preset {
    /// The preset a name (`"luma"`) names.
    pub fn from_name(name: &str) -> Option<Preset> {
        match name {
            "luma" | "deck" | "deck.gl" | "luma.gl" => Some(Preset::Luma),
            "three" | "three.js" => Some(Preset::Three),
            _ => None,
        }
    }

    /// Its name.
    pub fn as_str(self) -> &'static str {
        match self {
            Preset::Luma => "luma",
            Preset::Three => "three",
        }
    }
}

/// Why a preset could not read its library.
#[derive(Clone, Debug, thiserror::Error)]
#[non_exhaustive]
pub enum PresetError {
    /// The library is not installed above the shader's folder.
    #[error(
        "the `{preset}` preset needs the `{package}` package, and no `node_modules/{package}` \
         is at or above `{}` (install it with npm)",
        .dir.display()
    )]
    NoPackage {
        /// The preset.
        preset: &'static str,
        /// The package.
        package: &'static str,
        /// Where it was looked for from.
        dir: PathBuf,
    },
    /// Node.js could not be started.
    #[error(
        "the preset reads the installed library with Node.js, which could not be started: {0} \
         (install Node.js, or set ESSL_NODE to its path)"
    )]
    NoNode(String),
    /// The preset's script failed.
    #[error("the preset's script failed: {0}")]
    Script(String),
}

/// A shader as a library assembles it: text before the author's (and after), with the
/// project's own module code in it, around the author's text (without its first line, where
/// the library drops it).
#[derive(Clone, Debug)]
pub(crate) struct Wrap {
    /// The author's literal.
    pub literal: Literal,
    /// The text before the author's.
    pub prefix: String,
    /// The text after.
    pub suffix: String,
    /// Where the author's text starts being used (past a first line the library drops).
    pub from: usize,
    /// How much of the author's text is used.
    pub len: usize,
    /// Module texts of the project found in `prefix`, mapped to their files.
    pub locals: Vec<Literal>,
    /// Runs of the author's text the library replaces (`#include <chunk>` lines, by the
    /// chunk's text), as ranges of the literal's text, in order.
    pub replaced: Vec<(std::ops::Range<usize>, String)>,
}

impl Wrap {
    /// Wraps `literal` into the library's text `assembled`, if the author's text (after its
    /// first line, when `drop_first_line`) is in it as written.
    pub fn new(
        literal: Literal,
        assembled: &str,
        drop_first_line: bool,
        locals: Vec<Literal>,
    ) -> Option<Wrap> {
        let text = &literal.text;
        let from = if drop_first_line {
            text.find('\n').map_or(text.len(), |n| n + 1)
        } else {
            0
        };
        let core = text[from..].trim_end();
        let at = if core.is_empty() {
            assembled.len()
        } else {
            assembled.rfind(core)?
        };
        Some(Wrap {
            prefix: assembled[..at].to_string(),
            suffix: assembled[at + core.len()..].to_string(),
            from,
            len: core.len(),
            literal,
            locals,
            replaced: Vec::new(),
        })
    }

    /// `literal` after `prefix`, whole, with the runs `replaced` of its text replaced.
    pub fn around(
        literal: Literal,
        prefix: String,
        replaced: Vec<(std::ops::Range<usize>, String)>,
    ) -> Wrap {
        Wrap {
            prefix,
            suffix: String::new(),
            from: 0,
            len: literal.text.len(),
            literal,
            locals: Vec::new(),
            replaced,
        }
    }

    /// The assembled text with the map back to the files.
    pub fn assembly(&self) -> Assembly {
        let author = from_pieces(&self.literal.file, &self.literal.pieces);
        let anchor = author
            .map_span(Span::empty(0))
            .map_or(0, |(_, s)| s.start as usize);
        let mut a = Assembly::default();
        let own = a.file_index(&self.literal.file);
        let mut cursor = 0;
        for local in &self.locals {
            let body = local.text.trim_end();
            if body.is_empty() {
                continue;
            }
            let Some(found) = self.prefix[cursor..].find(body) else {
                continue;
            };
            let at = cursor + found;
            a.generated(&self.prefix[cursor..at], own, anchor);
            let module = from_pieces(&local.file, &local.pieces);
            a.extend_from(&module, 0..body.len());
            cursor = at + body.len();
        }
        a.generated(&self.prefix[cursor..], own, anchor);
        let range = self.from..self.from + self.len;
        replace_runs(&mut a, &author, range, &self.replaced, own, anchor);
        let end = author
            .map_span(Span::empty((self.from + self.len) as u32))
            .map_or(anchor, |(_, s)| s.start as usize);
        a.generated(&self.suffix, own, end);
        a
    }
}

/// Appends `range` of `author` to `a` with the runs `replaced` (in order, apart, within
/// `range`) replaced by their texts, each generated at the place its run starts.
fn replace_runs(
    a: &mut Assembly,
    author: &Assembly,
    range: std::ops::Range<usize>,
    replaced: &[(std::ops::Range<usize>, String)],
    own: u32,
    anchor: usize,
) {
    let mut at = range.start;
    for (run, text) in replaced {
        a.extend_from(author, at..run.start);
        let near = author
            .map_span(Span::empty(run.start as u32))
            .map_or(anchor, |(_, s)| s.start as usize);
        a.generated(text, own, near);
        at = run.end;
    }
    a.extend_from(author, at..range.end);
}

/// A chunk's text as its preset's library rewrites every shader's text (three.js: light
/// counts, unrolled loops); as written for other presets.
pub(crate) fn chunk(author: Assembly, preset: Option<Preset>) -> Assembly {
    if preset != Some(Preset::Three) {
        return author;
    }
    let runs = three::rewrites(author.text());
    let Some((f, at)) = author.map_span(Span::empty(0)) else {
        return author;
    };
    if runs.is_empty() {
        return author;
    }
    let mut a = Assembly::default();
    let own = a.file_index(&author.files()[f as usize]);
    replace_runs(
        &mut a,
        &author,
        0..author.text().len(),
        &runs,
        own,
        at.start as usize,
    );
    a
}

/// A program a preset assembled.
#[derive(Clone, Debug)]
pub(crate) struct Assembled {
    /// Where its object starts in its host.
    pub object: usize,
    /// Its vertex shader, wrapped.
    pub vs: Option<Wrap>,
    /// Its fragment shader, wrapped.
    pub fs: Option<Wrap>,
    /// Why it could not be assembled, if it could not.
    pub error: Option<String>,
    /// Why it is not checked, if it is not: a value it needs is known only when the script
    /// runs.
    pub unchecked: Option<String>,
    /// What the library refused in its shaders (an `#include` of a chunk it does not have),
    /// each at its place.
    pub problems: Vec<(Arc<essl::source::SourceFile>, essl::diagnostic::Diagnostic)>,
}

/// What a run's presets prepared, by host file (canonical path).
#[derive(Debug, Default)]
pub struct Prepared {
    /// The programs assembled whose objects lie in each host.
    pub(crate) programs: HashMap<PathBuf, Vec<Assembled>>,
    /// The literals those programs hold: (host, where the literal starts). Their own hosts
    /// leave them to the programs.
    pub(crate) claimed: HashSet<(PathBuf, usize)>,
    /// `#version` shaders no program claims, wrapped as the library assembles a shader with
    /// no modules.
    pub(crate) lone: HashMap<(PathBuf, usize), Wrap>,
    /// Hosts a preset applies to but could not be read for, and why.
    pub(crate) failed: HashMap<PathBuf, PresetError>,
}

/// A path as the prepared maps key it.
pub(crate) fn key(path: &Path) -> PathBuf {
    std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf())
}
