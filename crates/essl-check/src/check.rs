//! Checking one unit of work — a shader file, a `NAME.vert` + `NAME.frag` pair, or the shaders
//! of one host file — with the settings of its folder: assemble each shader's text (a host's
//! range, `#include`s in place), apply `--fix` in rounds to the unit's own file, compile, lint,
//! link, and move every diagnostic onto the file the author wrote.

use std::path::PathBuf;
use std::sync::Arc;

use essl::diagnostic::{apply_fixes, Applicability, Diagnostic};
use essl::source::SourceFile;
use essl::{Shader, Stage};

use crate::assembly::Assembly;
use crate::chunk::{chunk_prelude, FREE_IN_A_CHUNK};
use crate::codes::CheckCode;
use crate::extract::{self, Embedded, Piece};
use crate::find::{Found, Host, Input};
use crate::include::{self, InFile};
use crate::preset::{self, Assembled, Prepared};
use crate::read::Files;
use crate::result::{
    CheckedProgram, CheckedShader, CheckedUnit, FileDiagnostics, FixedFile, ProgramDiagnostic,
    Unread,
};
use crate::settings::{Configs, Settings};

/// How many rounds of fixes `--fix` applies at most: a fix can unlock another (a parse that
/// recovers further once a `;` is in place), and a few rounds reach a fixed point in practice.
pub const MAX_FIX_ROUNDS: usize = 8;

/// Which fixes to apply to the files checked.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum FixMode {
    /// None: report only.
    #[default]
    Off,
    /// The certain fixes (`--fix`).
    Certain,
    /// The certain fixes, then the suggested ones where no certain one applies
    /// (`--fix --unsafe-fixes`).
    Suggested,
}

/// How far to take each shader.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Phase {
    /// Everything: the front end and, where the lints run, lowering to naga IR and the lints.
    /// Without the lints a check is what WebGL answers (the front end and the linker):
    /// lowering, which only the lints and the translators read, fails only where essl cannot
    /// translate valid GLSL ES, and costs about as much as the front end.
    #[default]
    Full,
    /// The front end alone; [`crate::finish`] does the rest later (an editor publishes the
    /// front end's diagnostics first).
    FrontEnd,
}

/// What a check does beyond the settings of each folder.
#[derive(Clone, Copy, Debug)]
pub struct CheckOptions {
    /// Link the pairs (`NAME.vert` + `NAME.frag`, and those a host file makes plain).
    pub link: bool,
    /// Run the numerical-hazard lints.
    pub lints: bool,
    /// Which fixes to apply.
    pub fix: FixMode,
    /// How far to take each shader.
    pub phase: Phase,
}

impl Default for CheckOptions {
    fn default() -> CheckOptions {
        CheckOptions {
            link: true,
            lints: true,
            fix: FixMode::Off,
            phase: Phase::Full,
        }
    }
}

/// A unit of work.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unit {
    /// One shader file (or text): an index into [`Found::inputs`].
    Single(usize),
    /// A `NAME.vert` + `NAME.frag` pair, compiled and linked together.
    Pair(usize, usize),
    /// The shaders of one host file: an index into [`Found::hosts`].
    Host(usize),
}

/// The units of work of what a search found: the pairs to link (when `link`), every unpaired
/// shader file, and one unit per host file.
pub fn units(found: &Found, link: bool) -> Vec<Unit> {
    let shader_files: Vec<crate::ShaderFile> = found
        .inputs
        .iter()
        .map(|i| crate::ShaderFile {
            path: i.path.clone(),
            stage: i.stage,
        })
        .collect();
    let pairs = if link {
        crate::pairs::pairs(&shader_files)
    } else {
        Vec::new()
    };
    let mut paired = vec![false; found.inputs.len()];
    let mut units: Vec<Unit> = Vec::with_capacity(found.inputs.len() + found.hosts.len());
    for &(v, f) in &pairs {
        paired[v] = true;
        paired[f] = true;
        units.push(Unit::Pair(v, f));
    }
    units.extend(
        (0..found.inputs.len())
            .filter(|&i| !paired[i])
            .map(Unit::Single),
    );
    units.extend((0..found.hosts.len()).map(Unit::Host));
    units
}

/// One shader of a unit, assembled but not compiled yet.
struct Part {
    /// The file it lies in, where that is not the unit's own (a shader a preset's program
    /// takes from another file).
    own: Option<(PathBuf, Arc<SourceFile>)>,
    stage: Stage,
    name: Option<String>,
    embedded_at: Option<u32>,
    /// Whether it is a chunk, checked as a library.
    chunk: bool,
    /// The assembled text, or why it could not be assembled.
    assembly: Result<Assembly, Vec<InFile>>,
}

/// What a unit needs besides itself.
pub(crate) struct Context<'a> {
    pub configs: &'a Configs,
    pub files: &'a Files,
    pub options: CheckOptions,
    pub prepared: &'a Prepared,
}

/// Checks one unit of what `found` holds.
pub(crate) fn check_unit(unit: Unit, found: &Found, cx: &Context) -> CheckedUnit {
    match unit {
        Unit::Single(i) => single(&found.inputs[i], i, cx),
        Unit::Pair(v, f) => {
            let mut out = single(&found.inputs[v], v, cx);
            let fragment = single(&found.inputs[f], f, cx);
            out.fixed.extend(fragment.fixed);
            out.unread.extend(fragment.unread);
            out.shaders.extend(fragment.shaders);
            if out.shaders.len() == 2 {
                out.programs.push(link(&out.shaders, 0, 1));
            }
            out
        }
        Unit::Host(h) => {
            let order =
                found.inputs.len() + found.hosts[..h].iter().map(|x| x.checked()).sum::<usize>();
            host(&found.hosts[h], order, cx)
        }
    }
}

/// A shader file or a text.
fn single(input: &Input, order: usize, cx: &Context) -> CheckedUnit {
    let file = match &input.text {
        Some(t) => Ok(Arc::new(SourceFile::new(
            input.path.display().to_string(),
            t.to_string(),
        ))),
        None => cx.files.read_once(&input.path),
    };
    let file = match file {
        Ok(f) => f,
        Err(e) => {
            return CheckedUnit {
                unread: vec![Unread {
                    order,
                    path: input.path.clone(),
                    stage: input.stage,
                    message: e.to_string(),
                }],
                ..CheckedUnit::default()
            }
        }
    };
    let Ok(settings) = cx.configs.for_file(&input.path) else {
        return CheckedUnit::default();
    };
    let make = |file: &Arc<SourceFile>| {
        let mut source = Assembly::whole(file.clone());
        if input.chunk {
            source = chunk_prelude(source, input.stage, &settings, &[]);
        }
        vec![Part {
            own: None,
            stage: input.stage,
            name: None,
            embedded_at: None,
            chunk: input.chunk,
            assembly: includes(source, &input.path, &settings, cx.files),
        }]
    };
    let (after, parts, applied) = fix_rounds(file.clone(), &make, &settings, cx.options);
    let mut unit = CheckedUnit::default();
    if applied > 0 {
        unit.fixed.push(fixed_file(
            &input.path,
            &file,
            &after,
            applied,
            input.text.is_some(),
        ));
    }
    let file = after;
    unit.shaders = finish_parts(parts, &input.path, order, &file, &settings, cx.options);
    for s in &mut unit.shaders {
        s.given = input.text.is_some();
    }
    unit
}

/// The shaders of a host file, and the programs it makes plain (or that a preset assembles
/// from its code).
fn host(h: &Host, order: usize, cx: &Context) -> CheckedUnit {
    let Ok(settings) = cx.configs.for_file(&h.path) else {
        return CheckedUnit::default();
    };
    let k = preset::key(&h.path);
    let prepared = cx.prepared;
    let programs = prepared.programs.get(&k).map_or(&[][..], Vec::as_slice);
    let embedded_of = |file: &Arc<SourceFile>| -> Vec<Embedded> {
        let all = if Arc::ptr_eq(file, &h.file) {
            h.embedded.clone()
        } else {
            Host::extract(&h.path, h.kind, file.text())
        };
        // A shader a preset's program holds is checked with the program.
        all.into_iter()
            .filter(|e| !prepared.claimed.contains(&(k.clone(), e.literal)))
            .collect()
    };
    let make = |file: &Arc<SourceFile>| -> Vec<Part> {
        let mut parts: Vec<Part> = embedded_of(file)
            .into_iter()
            .filter_map(|e| {
                let stage = e.stage.filter(|_| e.skip.is_none())?;
                let source = match prepared.lone.get(&(k.clone(), e.literal)) {
                    Some(wrap) => wrap.assembly(),
                    None if e.chunk => {
                        let text = preset::chunk(from_pieces(file, &e.pieces), settings.preset);
                        chunk_prelude(text, stage, &settings, &e.defines)
                    }
                    None => from_pieces(file, &e.pieces),
                };
                Some(Part {
                    own: None,
                    stage,
                    name: e.name,
                    embedded_at: Some(e.range.start as u32),
                    chunk: e.chunk,
                    assembly: includes(source, &h.path, &settings, cx.files),
                })
            })
            .collect();
        if let Some(e) = prepared.failed.get(&k) {
            parts.push(problem(
                file,
                0,
                CheckCode::PresetUnavailable,
                e.to_string(),
            ));
        }
        for p in programs {
            parts.extend(program_parts(p, file));
        }
        parts
    };
    // The text a preset's library assembles is made once a run: a host it assembles is not
    // fixed in rounds.
    let fixing = programs.is_empty() && !prepared.lone.keys().any(|(host, _)| *host == k);
    let options = CheckOptions {
        fix: if fixing { cx.options.fix } else { FixMode::Off },
        ..cx.options
    };
    let (file, parts, applied) = fix_rounds(h.file.clone(), &make, &settings, options);
    let mut unit = CheckedUnit::default();
    if applied > 0 {
        unit.fixed
            .push(fixed_file(&h.path, &h.file, &file, applied, h.stdin));
    }
    let found = embedded_of(&file);
    let checked: Vec<usize> = (0..found.len())
        .filter(|&k| found[k].skip.is_none() && found[k].stage.is_some())
        .collect();
    let mut pairs: Vec<(usize, usize)> = if cx.options.link {
        // Chunks are parts too, but never paired (extract::pairs leaves them out).
        let part_of = |k: usize| checked.iter().position(|&c| c == k);
        extract::pairs(&found)
            .into_iter()
            .filter_map(|(v, f)| Some((part_of(v)?, part_of(f)?)))
            .collect()
    } else {
        Vec::new()
    };
    let mut next = checked.len() + prepared.failed.contains_key(&k) as usize;
    for p in programs {
        let n = program_parts(p, &file).len();
        if n == 2 && cx.options.link {
            pairs.push((next, next + 1));
        }
        next += n;
    }
    unit.shaders = finish_parts(parts, &h.path, order, &file, &settings, cx.options);
    for s in &mut unit.shaders {
        s.given = h.stdin;
    }
    for (v, f) in pairs {
        unit.programs.push(link(&unit.shaders, v, f));
    }
    unit
}

/// The shaders of a program a preset assembled, or the error that it could not be.
fn program_parts(p: &Assembled, host: &Arc<SourceFile>) -> Vec<Part> {
    if let Some(e) = &p.error {
        return vec![problem(
            host,
            p.object,
            CheckCode::PresetAssembly,
            e.clone(),
        )];
    }
    if let Some(why) = &p.unchecked {
        let mut part = problem(host, p.object, CheckCode::PresetUnchecked, why.clone());
        if let Err(ds) = &mut part.assembly {
            for (_, d) in ds.iter_mut() {
                d.severity = essl::diagnostic::Severity::Note;
            }
        }
        return vec![part];
    }
    if !p.problems.is_empty() {
        return vec![Part {
            own: None,
            stage: Stage::Vertex,
            name: None,
            embedded_at: Some(p.object as u32),
            chunk: false,
            assembly: Err(p.problems.clone()),
        }];
    }
    [(&p.vs, Stage::Vertex), (&p.fs, Stage::Fragment)]
        .into_iter()
        .filter_map(|(w, stage)| {
            let w = w.as_ref()?;
            let a = w.assembly();
            let at = a.map_span(essl::source::Span::empty(a.text().len() as u32));
            let file = w.literal.file.clone();
            let start = preset_start(w);
            let _ = at;
            Some(Part {
                own: Some((PathBuf::from(file.name()), file)),
                stage,
                name: None,
                embedded_at: Some(start),
                chunk: false,
                assembly: Ok(a),
            })
        })
        .collect()
}

/// Where a wrapped literal's text starts in its file.
fn preset_start(w: &preset::Wrap) -> u32 {
    w.literal
        .pieces
        .iter()
        .find_map(|p| match p {
            Piece::Raw(r) | Piece::Cooked { raw: r, .. } => Some(r.start as u32),
            _ => None,
        })
        .unwrap_or(w.literal.at as u32)
}

/// A part that is only an error at byte `at` of `file`.
fn problem(file: &Arc<SourceFile>, at: usize, code: CheckCode, message: String) -> Part {
    let span = essl::source::Span::empty(at as u32);
    let d = Diagnostic::new(
        essl::diagnostic::Severity::Error,
        code.as_str(),
        message,
        span,
    );
    Part {
        own: None,
        stage: Stage::Vertex,
        name: None,
        embedded_at: Some(at as u32),
        chunk: false,
        assembly: Err(vec![(file.clone(), d)]),
    }
}

fn fixed_file(
    path: &std::path::Path,
    before: &Arc<SourceFile>,
    after: &Arc<SourceFile>,
    applied: usize,
    stdin: bool,
) -> FixedFile {
    FixedFile {
        path: path.to_path_buf(),
        before: before.clone(),
        after: after.text().to_string(),
        applied,
        stdin,
    }
}

/// The text of an embedded shader: its pieces of `file` (and of the files its substitutions
/// import).
pub(crate) fn from_pieces(file: &Arc<SourceFile>, pieces: &[Piece]) -> Assembly {
    fn push(a: &mut Assembly, f: u32, pieces: &[Piece]) {
        for p in pieces {
            match p {
                Piece::Raw(r) => a.verbatim(f, r.clone()),
                Piece::Cooked { raw, value } => a.cooked(f, raw.clone(), value),
                Piece::Added { text, at } => a.generated(text, f, *at),
                Piece::From { file, pieces } => {
                    let g = a.file_index(file);
                    push(a, g, pieces);
                }
            }
        }
    }
    let mut a = Assembly::default();
    let f = a.file_index(file);
    push(&mut a, f, pieces);
    a
}

/// Whether a diagnostic is the author's to see: a warning or lint finding inside code a
/// library adds (a luma.gl module's `1.0 / 0.0`, three.js's prelude) is the library's, not
/// reported; an error there is, since the program does not compile.
fn shown(a: &Assembly, d: &Diagnostic) -> bool {
    d.is_error() || !a.is_generated(d.span.start)
}

/// `source` with its `#include`s in place, where the settings follow them.
fn includes(
    source: Assembly,
    path: &std::path::Path,
    settings: &Settings,
    files: &Files,
) -> Result<Assembly, Vec<InFile>> {
    match &settings.include {
        Some(dirs) if include::has_include(source.text()) => {
            include::expand(&source, path, dirs, files)
        }
        _ => Ok(source),
    }
}

type Compiled = (Part, Option<Shader>);

/// Compiles the parts `make` assembles from `file`; under `--fix`, applies the fixes that fall
/// in `file` and compiles again, until none applies. Returns the final text of the file, its
/// parts compiled, and how many fixes were applied.
fn fix_rounds(
    file: Arc<SourceFile>,
    make: &dyn Fn(&Arc<SourceFile>) -> Vec<Part>,
    settings: &Settings,
    options: CheckOptions,
) -> (Arc<SourceFile>, Vec<Compiled>, usize) {
    let mut current = file;
    let mut applied = 0;
    let lower = options.phase == Phase::Full && options.lints;
    for round in 0..=MAX_FIX_ROUNDS {
        let compiled: Vec<Compiled> = make(&current)
            .into_iter()
            .map(|p| {
                let shader = compile(&p, settings, lower);
                (p, shader)
            })
            .collect();
        if options.fix == FixMode::Off || round == MAX_FIX_ROUNDS {
            return (current, compiled, applied);
        }
        let own: Vec<Diagnostic> = compiled
            .iter()
            .filter_map(|(p, s)| Some((p.assembly.as_ref().ok()?, s.as_ref()?)))
            .flat_map(|(a, s)| {
                s.diagnostics
                    .iter()
                    .filter(|d| d.fix.is_some())
                    .map(|d| a.map_diagnostic(d.clone()))
                    .filter(|(f, _)| Arc::ptr_eq(&a.files()[*f as usize], &current))
                    .map(|(_, d)| d)
                    .collect::<Vec<_>>()
            })
            .collect();
        let (mut text, mut n) = apply_fixes(current.text(), &own, Applicability::Certain);
        if n == 0 && options.fix == FixMode::Suggested {
            (text, n) = apply_fixes(current.text(), &own, Applicability::Suggested);
        }
        if n == 0 || text == current.text() {
            return (current, compiled, applied);
        }
        applied += n;
        current = Arc::new(SourceFile::new(current.name(), text));
    }
    unreachable!("the last round returns")
}

/// Compiles one part (nothing where its includes failed), lowered to naga IR when `lower` and a
/// lint on the IR has something to look at ([`essl_lint::lower_for_lints`]).
fn compile(part: &Part, settings: &Settings, lower: bool) -> Option<Shader> {
    let assembly = part.assembly.as_ref().ok()?;
    let name = assembly
        .files()
        .first()
        .map_or(String::new(), |f| f.name().to_string());
    let file = SourceFile::new(name, assembly.text());
    let mut shader = essl::compile_front_end(file, part.stage, &settings.compile);
    if lower {
        essl_lint::lower_for_lints(&mut shader, &settings.rules);
    }
    Some(shader)
}

/// Lints the compiled parts and moves their diagnostics onto their files.
fn finish_parts(
    parts: Vec<Compiled>,
    path: &std::path::Path,
    order: usize,
    own: &Arc<SourceFile>,
    settings: &Arc<Settings>,
    options: CheckOptions,
) -> Vec<CheckedShader> {
    parts
        .into_iter()
        .enumerate()
        .map(|(k, (part, shader))| {
            let (path, own) = match &part.own {
                Some((p, f)) => (p.as_path(), f),
                None => (path, own),
            };
            let (diagnostics, assembly) = match part.assembly {
                Ok(a) => {
                    let free = |d: &&Diagnostic| !(part.chunk && FREE_IN_A_CHUNK.contains(&d.code));
                    let all = shader.iter().flat_map(|s| &s.diagnostics).filter(free);
                    (group(own, &a, all.filter(|d| shown(&a, d))), a)
                }
                Err(errors) => (group_in_files(own, errors), Assembly::default()),
            };
            let mut checked = CheckedShader {
                order: order + k,
                path: path.to_path_buf(),
                stage: part.stage,
                embedded_at: part.embedded_at,
                name: part.name,
                shader,
                assembly,
                diagnostics,
                linted: false,
                given: false,
                settings: settings.clone(),
            };
            if options.phase == Phase::Full && !part.chunk {
                lint(&mut checked, settings, options.lints);
            }
            checked.linted |= part.chunk;
            checked
        })
        .collect()
}

/// Lowers a shader checked by its front end alone where a lint on naga IR has something to look
/// at, and runs the lints (when `lints`: a check without them is left unlowered), adding their
/// findings on their files.
pub(crate) fn lint(checked: &mut CheckedShader, settings: &Settings, lints: bool) {
    if checked.linted {
        return;
    }
    checked.linted = true;
    let Some(shader) = checked.shader.as_mut().filter(|_| lints) else {
        return;
    };
    let before = shader.diagnostics.len();
    essl_lint::lower_for_lints(shader, &settings.rules);
    let mut found: Vec<Diagnostic> = shader.diagnostics[before..].to_vec();
    if shader.ok() {
        found.extend(essl_lint::lint(shader, &settings.rules));
        if settings.variants > 0 {
            let assembly = &checked.assembly;
            // The flags of the author's text: a library's own (three.js's chunks) are its
            // business.
            let flags: Vec<_> = essl_lint::variants::flags(shader.file.text(), &settings.compile)
                .into_iter()
                .filter(|v| !assembly.is_generated(v.directive.start))
                .collect();
            let more = essl_lint::variants::lint(
                shader,
                &settings.compile,
                &settings.rules,
                &found,
                &flags,
                settings.variants,
            );
            found.extend(more.into_iter().map(|f| f.diagnostic));
            essl::diagnostic::sort(&mut found);
        }
    }
    if found.is_empty() {
        return;
    }
    let own = checked.file().clone();
    let more = group(
        &own,
        &checked.assembly,
        found.iter().filter(|d| shown(&checked.assembly, d)),
    );
    for g in more {
        match checked
            .diagnostics
            .iter_mut()
            .find(|x| Arc::ptr_eq(&x.file, &g.file))
        {
            Some(x) => {
                x.diagnostics.extend(g.diagnostics);
                essl::diagnostic::sort(&mut x.diagnostics);
            }
            None => checked.diagnostics.push(g),
        }
    }
}

/// Diagnostics of `assembly`'s text moved onto their files: `own` first (even with none),
/// then each other file in the order the assembly met it.
fn group<'a>(
    own: &Arc<SourceFile>,
    assembly: &Assembly,
    diagnostics: impl Iterator<Item = &'a Diagnostic>,
) -> Vec<FileDiagnostics> {
    let mut out = vec![FileDiagnostics {
        file: own.clone(),
        diagnostics: Vec::new(),
    }];
    for d in diagnostics {
        let (f, d) = assembly.map_diagnostic(d.clone());
        let file = assembly.files().get(f as usize).unwrap_or(own);
        push(&mut out, file, d);
    }
    for g in &mut out {
        essl::diagnostic::sort(&mut g.diagnostics);
    }
    out
}

fn group_in_files(own: &Arc<SourceFile>, errors: Vec<InFile>) -> Vec<FileDiagnostics> {
    let mut out = vec![FileDiagnostics {
        file: own.clone(),
        diagnostics: Vec::new(),
    }];
    for (file, d) in errors {
        push(&mut out, &file, d);
    }
    out
}

fn push(groups: &mut Vec<FileDiagnostics>, file: &Arc<SourceFile>, d: Diagnostic) {
    match groups.iter_mut().find(|g| Arc::ptr_eq(&g.file, file)) {
        Some(g) => g.diagnostics.push(d),
        None => groups.push(FileDiagnostics {
            file: file.clone(),
            diagnostics: vec![d],
        }),
    }
}

/// Links shaders `v` and `f` of a unit (when both compiled) and moves the link diagnostics
/// onto their files.
fn link(shaders: &[CheckedShader], v: usize, f: usize) -> CheckedProgram {
    link_shaders(&shaders[v], &shaders[f], v, f)
}

/// Links a vertex and a fragment shader (when both compiled); `v` and `f` are what the program
/// records as their indices.
pub(crate) fn link_shaders(
    vs: &CheckedShader,
    fs: &CheckedShader,
    v: usize,
    f: usize,
) -> CheckedProgram {
    let (Some(a), Some(b)) = (&vs.shader, &fs.shader) else {
        return CheckedProgram {
            vertex: v,
            fragment: f,
            program: None,
            linked: false,
            diagnostics: Vec::new(),
        };
    };
    let program = essl::link::link(a, b);
    let linked = vs.ok() && fs.ok();
    let diagnostics = program
        .diagnostics
        .iter()
        .map(|d| {
            let shader = match d.stage {
                Some(Stage::Vertex) => Some(vs),
                Some(Stage::Fragment) => Some(fs),
                None => None,
            };
            match shader {
                Some(s) => {
                    let (file, diagnostic) = s.assembly.map_diagnostic(d.diagnostic.clone());
                    ProgramDiagnostic {
                        file: s.assembly.files().get(file as usize).cloned(),
                        stage: d.stage,
                        diagnostic,
                    }
                }
                None => ProgramDiagnostic {
                    file: None,
                    stage: None,
                    diagnostic: d.diagnostic.clone(),
                },
            }
        })
        .filter(|_| linked)
        .collect();
    CheckedProgram {
        vertex: v,
        fragment: f,
        program: Some(program),
        linked,
        diagnostics,
    }
}
