//! The programs a JS/TS project assembles with luma.gl, read from its code: an object with
//! `vs`, `fs` and `modules` keys — what a deck.gl layer passes to `super.getShaders({…})` and a
//! luma.gl `Model` takes — its shaders followed to the literals that hold them (in the file or
//! in a file it imports), and each module to the package that exports it or to the module
//! object the project writes (`{name, vs, fs, defines, dependencies}`).

use std::path::Path;
use std::rc::Rc;
use std::sync::Arc;

use essl::source::SourceFile;

use crate::extract::js::objects::{self, Object};
use crate::extract::js::{self, literal, scan, Binding, Export};
use crate::extract::{text_of, Piece};
use crate::imports::{DiskImports, Script};

use super::resolve;

/// How deep module dependencies written in the project are followed.
const MAX_DEPTH: usize = 8;

/// A literal that holds a shader's (or a module's) text.
#[derive(Clone, Debug)]
pub struct Literal {
    /// The file that holds it.
    pub file: Arc<SourceFile>,
    /// Where its expression starts in the file.
    pub at: usize,
    /// Its value, as pieces of the file.
    pub pieces: Vec<Piece>,
    /// Its value.
    pub text: String,
}

/// A module a program names.
#[derive(Clone, Debug)]
pub enum ModuleRef {
    /// An export of a package (`import {picking} from '@deck.gl/core'`).
    Package {
        /// The package.
        package: String,
        /// The name it exports.
        export: String,
    },
    /// A module object the project writes.
    Local(Box<LocalModule>),
}

/// A module object written in the project.
#[derive(Clone, Debug, Default)]
pub struct LocalModule {
    /// Its `name`.
    pub name: String,
    /// Its `vs` text.
    pub vs: Option<Literal>,
    /// Its `fs` text.
    pub fs: Option<Literal>,
    /// Its `defines`.
    pub defines: Vec<(String, String)>,
    /// Its `dependencies`.
    pub dependencies: Vec<ModuleRef>,
}

/// A program the project assembles.
#[derive(Clone, Debug)]
pub struct Program {
    /// Where its object starts in its file.
    pub object: usize,
    /// Whether it is a deck.gl layer's (`…getShaders({…})`): deck.gl's default modules and
    /// hooks then apply.
    pub deck: bool,
    /// Its vertex shader.
    pub vs: Option<Literal>,
    /// Its fragment shader.
    pub fs: Option<Literal>,
    /// Its modules, as named.
    pub modules: Vec<ModuleRef>,
    /// Its `defines`, where they are literals.
    pub defines: Vec<(String, String)>,
    /// Names the modules list holds that essl could not follow.
    pub unknown: Vec<String>,
}

/// How many programs one object may stand for (`vs: top ? a : b`).
const MAX_VARIANTS: usize = 4;

/// The programs of the script `script` (a host of the run).
pub fn programs(script: &Rc<Script>, imports: &DiskImports) -> Vec<Program> {
    programs_to(script, imports, 0)
}

fn programs_to(script: &Rc<Script>, imports: &DiskImports, depth: usize) -> Vec<Program> {
    let text = script.file.text();
    objects::objects_with(text, &["vs", "fs"])
        .into_iter()
        .filter(|o| o.get("modules").is_some() || o.callee.ends_with("getShaders"))
        .filter(|o| o.get("name").is_none())
        .flat_map(|o| program(script, &o, imports, depth))
        .collect()
}

/// The programs an object stands for: one, or one per alternative of a `?:` among its
/// shaders.
fn program(script: &Rc<Script>, o: &Object, imports: &DiskImports, depth: usize) -> Vec<Program> {
    let text = script.file.text();
    let shaders = |key: &str| -> Vec<Option<Literal>> {
        let Some(value) = o.get(key) else {
            return vec![None];
        };
        alternatives(text, value)
            .into_iter()
            .map(|r| {
                let (s, at) = value_position(script, r, imports)?;
                literal_at(&s, at, imports)
            })
            .collect()
    };
    let mut unknown = Vec::new();
    let mut deck = o.callee.ends_with("getShaders");
    // Each module element's alternatives, and the modules a spread of a base class's
    // `super.getShaders()` brings.
    let mut choices: Vec<Vec<ModuleRef>> = Vec::new();
    for element in o
        .get("modules")
        .map(|r| elements(text, r))
        .unwrap_or_default()
    {
        let code = text[element.clone()].trim();
        if let Some(spread) = code.strip_prefix("...") {
            if spread.trim_end().ends_with(".modules") {
                if let Some(base) = base_program(script, imports, depth) {
                    deck |= base.deck;
                    choices.extend(base.modules.into_iter().map(|m| vec![m]));
                }
            }
            continue;
        }
        // A module chosen by `?:` (`flatShading ? phongMaterial : gouraudMaterial`) is taken
        // in its last alternative: the default configuration, whose macros the code leaves at
        // their defaults too (`FLAT_SHADING` undefined). Shaders chosen by `?:` are each a
        // program the code draws with.
        let options: Vec<ModuleRef> = alternatives(text, element)
            .into_iter()
            .last()
            .into_iter()
            .filter_map(|r| {
                let name = text[r].trim().to_string();
                let m = module_ref(script, &name, imports, 0);
                if m.is_none() {
                    unknown.push(name);
                }
                m
            })
            .collect();
        if !options.is_empty() {
            choices.push(options);
        }
    }
    let defines = o
        .get("defines")
        .map(|r| defines(script, r.start, imports))
        .unwrap_or_default();
    let mut out = Vec::new();
    for vs in shaders("vs") {
        for fs in shaders("fs") {
            for modules in variants(&choices) {
                if out.len() < MAX_VARIANTS {
                    out.push(Program {
                        object: o.open,
                        deck,
                        vs: vs.clone(),
                        fs: fs.clone(),
                        modules,
                        defines: defines.clone(),
                        unknown: unknown.clone(),
                    });
                }
            }
        }
    }
    out
}

/// One list of modules per way of choosing among each element's alternatives (at most
/// [`MAX_VARIANTS`]).
fn variants(choices: &[Vec<ModuleRef>]) -> Vec<Vec<ModuleRef>> {
    let mut out: Vec<Vec<ModuleRef>> = vec![Vec::new()];
    for options in choices {
        let mut next = Vec::new();
        for prefix in &out {
            for m in options {
                if next.len() < MAX_VARIANTS {
                    let mut v = prefix.clone();
                    v.push(m.clone());
                    next.push(v);
                }
            }
        }
        out = next;
    }
    out
}

/// The program of the base class this script's class extends (`class MultiIconLayer extends
/// IconLayer`): what `super.getShaders()` gives.
fn base_program(script: &Rc<Script>, imports: &DiskImports, depth: usize) -> Option<Program> {
    if depth > MAX_DEPTH {
        return None;
    }
    let text = script.file.text();
    let base = text
        .match_indices("class ")
        .find_map(|(at, _)| class_base(text, at + "class ".len()))?;
    let there = match script.consts.names.get(base)? {
        Binding::Import { from, .. } => imported(script, from, imports)?,
        Binding::Local(_) => script.clone(),
    };
    programs_to(&there, imports, depth + 1).into_iter().next()
}

/// The names an array literal holds (`[lighting, fp32]`; other elements left out).
fn names(text: &str, range: std::ops::Range<usize>) -> Vec<String> {
    elements(text, range)
        .into_iter()
        .map(|r| text[r].trim().to_string())
        .filter(|n| {
            let b = n.as_bytes();
            scan::ident_at(b, 0).is_some_and(|r| r.end == b.len())
        })
        .collect()
}

/// The class a `class NAME<…> extends BASE<…> {` header extends (angle brackets, which may
/// hold `extends` and `{}` of their own, skipped).
fn class_base(text: &str, from: usize) -> Option<&str> {
    let b = text.as_bytes();
    let mut depth = 0usize;
    let mut i = from;
    while i < b.len() {
        match b[i] {
            b'<' => depth += 1,
            b'>' => depth = depth.saturating_sub(1),
            b'{' if depth == 0 => return None,
            b'e' if depth == 0
                && text[i..].starts_with("extends ")
                && !scan::is_ident(b[i - 1]) =>
            {
                let at = scan::skip_trivia(b, i + "extends ".len());
                let r = scan::ident_at(b, at)?;
                return Some(&text[r]);
            }
            _ => {}
        }
        i += 1;
    }
    None
}

/// The elements of an array literal `[a, b ? c : d, ...e]`, as ranges.
fn elements(text: &str, range: std::ops::Range<usize>) -> Vec<std::ops::Range<usize>> {
    let b = text.as_bytes();
    let open = scan::skip_trivia(b, range.start);
    if b.get(open) != Some(&b'[') {
        return Vec::new();
    }
    split_top(
        text,
        open + 1..range.end.saturating_sub(1).max(open + 1),
        b',',
    )
}

/// `range` split at `sep` where it stands outside brackets, strings and comments.
fn split_top(text: &str, range: std::ops::Range<usize>, sep: u8) -> Vec<std::ops::Range<usize>> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut depth = 0usize;
    let mut start = range.start;
    let mut i = range.start;
    while i < range.end {
        match b[i] {
            b'/' if b.get(i + 1) == Some(&b'/') => i = scan::line_end(b, i),
            b'/' if b.get(i + 1) == Some(&b'*') => i = scan::comment_end(b, i),
            b'\'' | b'"' => i = scan::string_end(b, i),
            b'`' => i = scan::template(b, i, 0).end,
            b'(' | b'[' | b'{' => {
                depth += 1;
                i += 1;
            }
            b')' | b']' | b'}' => {
                depth = depth.saturating_sub(1);
                i += 1;
            }
            c if c == sep && depth == 0 => {
                out.push(start..i);
                i += 1;
                start = i;
            }
            _ => i += 1,
        }
    }
    if !text[start..range.end.min(b.len())].trim().is_empty() {
        out.push(start..range.end.min(b.len()));
    }
    out.retain(|r| !text[r.clone()].trim().is_empty());
    out
}

/// The alternatives of a value: `c ? x : y` → `x`, `y` (each split again); anything else is
/// its own one alternative.
fn alternatives(text: &str, range: std::ops::Range<usize>) -> Vec<std::ops::Range<usize>> {
    let parts = split_top(text, range.clone(), b'?');
    if parts.len() != 2 {
        return vec![range];
    }
    let branches = split_top(text, parts[1].clone(), b':');
    if branches.len() != 2 {
        return vec![range];
    }
    branches
        .into_iter()
        .flat_map(|r| alternatives(text, r))
        .collect()
}

/// The literal a shader-valued entry holds or names (`vertexShader: vs`), with its value.
pub fn shader_value(
    script: &Rc<Script>,
    value: std::ops::Range<usize>,
    imports: &DiskImports,
) -> Option<Literal> {
    let (s, at) = value_position(script, value, imports)?;
    literal_at(&s, at, imports)
}

/// Where the expression a value names starts, and in which script: the value itself when it
/// is a literal, else the constant or the export its name is bound to.
fn value_position(
    script: &Rc<Script>,
    value: std::ops::Range<usize>,
    imports: &DiskImports,
) -> Option<(Rc<Script>, usize)> {
    let text = script.file.text();
    let code = text[value.clone()].trim();
    if resolve::is_path(code) {
        resolve::path(script, value.start, code, imports, 0)
    } else {
        Some((script.clone(), value.start))
    }
}

/// Where the name `name` of `script` is bound to an expression.
pub(super) fn bound(
    script: &Rc<Script>,
    name: &str,
    imports: &DiskImports,
    depth: usize,
) -> Option<(Rc<Script>, usize)> {
    if depth > MAX_DEPTH {
        return None;
    }
    match script.consts.names.get(name)? {
        Binding::Local(at) => Some((script.clone(), *at)),
        Binding::Import { from, name } => {
            let there = imported(script, from, imports)?;
            exported(&there, name, imports, depth + 1)
        }
    }
}

/// The script a relative specifier of `script` names.
fn imported(script: &Rc<Script>, from: &str, imports: &DiskImports) -> Option<Rc<Script>> {
    if !from.starts_with('.') {
        return None;
    }
    let here = imports.at(script.path.parent().unwrap_or(Path::new("")));
    let path = here.resolve(from)?;
    here.script(&path)
}

/// Where the export `name` of `script` is bound.
fn exported(
    script: &Rc<Script>,
    name: &str,
    imports: &DiskImports,
    depth: usize,
) -> Option<(Rc<Script>, usize)> {
    match script.consts.exports.get(name)? {
        Export::Name(local) => bound(script, local, imports, depth),
        Export::Expr(at) => Some((script.clone(), *at)),
    }
}

/// The literal expression at `at` of `script`, with its value.
fn literal_at(script: &Rc<Script>, at: usize, imports: &DiskImports) -> Option<Literal> {
    let text = script.file.text();
    let (expr, end) = literal::parse(text.as_bytes(), at)?;
    if literal::rewritten(text.as_bytes(), end) {
        return None;
    }
    let here = imports.at(script.path.parent().unwrap_or(Path::new("")));
    let lookup = |n: &str, d: usize| js::lookup(text, &script.consts, &here, n, d);
    let pieces = expr.pieces(text, &lookup, 0).ok()?;
    Some(Literal {
        file: script.file.clone(),
        at,
        text: text_of(text, &pieces),
        pieces,
    })
}

/// What a module's name refers to.
fn module_ref(
    script: &Rc<Script>,
    name: &str,
    imports: &DiskImports,
    depth: usize,
) -> Option<ModuleRef> {
    if depth > MAX_DEPTH {
        return None;
    }
    if let Some(Binding::Import { from, name }) = script.consts.names.get(name) {
        if !from.starts_with('.') {
            return Some(ModuleRef::Package {
                package: from.clone(),
                export: name.clone(),
            });
        }
    }
    let (there, at) = bound(script, name, imports, 0)?;
    local_module(&there, at, imports, depth).map(|m| ModuleRef::Local(Box::new(m)))
}

/// The module object at `at` of `script`.
fn local_module(
    script: &Rc<Script>,
    at: usize,
    imports: &DiskImports,
    depth: usize,
) -> Option<LocalModule> {
    let text = script.file.text();
    if text.as_bytes().get(at) != Some(&b'{') {
        return None;
    }
    let o = objects::object(text, at)?;
    let string = |key: &str| -> Option<String> {
        let r = o.get(key)?;
        let lit = literal_at(script, r.start, imports)?;
        Some(lit.text)
    };
    let shader = |key: &str| {
        let (s, at) = value_position(script, o.get(key)?, imports)?;
        literal_at(&s, at, imports)
    };
    Some(LocalModule {
        name: string("name")?,
        vs: shader("vs"),
        fs: shader("fs"),
        defines: o
            .get("defines")
            .map(|r| defines(script, r.start, imports))
            .unwrap_or_default(),
        dependencies: o
            .get("dependencies")
            .map(|r| names(text, r))
            .unwrap_or_default()
            .iter()
            .filter_map(|n| module_ref(script, n, imports, depth + 1))
            .collect(),
    })
}

/// An object literal of macro values at `at` (`{USE_X: 1, SKIN_MAX_JOINTS}`): each entry whose
/// value essl can compute, as `NAME`, `VALUE`. A value known only when the script runs
/// (`ringWindingOrderCW`) still defines the macro, as 1: `#if NAME` then reads it, where
/// leaving it out would be an error.
pub fn defines(script: &Rc<Script>, at: usize, imports: &DiskImports) -> Vec<(String, String)> {
    define_values(script, at..at, imports)
        .unwrap_or_default()
        .into_iter()
        .map(|(k, v)| (k, v.unwrap_or_else(|| "1".to_string())))
        .collect()
}

/// The macros a `defines` value (an object literal, a name or path that leads to one, or
/// `Object.assign({}, A.defines, {…})` of those) gives: each name with its value where essl
/// can compute it; `None` when the value leads to no object the scripts write.
/// `Shader.defines` of an object `Shader` that has no `defines` key: none (three.js's
/// `Object.assign({}, Shader.defines)` then copies nothing).
fn no_defines_key(
    script: &Rc<Script>,
    value: std::ops::Range<usize>,
    imports: &DiskImports,
) -> Option<Vec<(String, Option<String>)>> {
    let code = script.file.text()[value.clone()].trim();
    let owner = code.strip_suffix(".defines")?;
    if !resolve::is_path(owner) {
        return None;
    }
    let (there, at) = resolve::path(script, value.start, owner, imports, 0)?;
    let o = objects::object(there.file.text(), at)?;
    o.get("defines").is_none().then(Vec::new)
}

pub fn define_values(
    script: &Rc<Script>,
    value: std::ops::Range<usize>,
    imports: &DiskImports,
) -> Option<Vec<(String, Option<String>)>> {
    merged_defines(script, value, imports, 0)
}

fn merged_defines(
    script: &Rc<Script>,
    value: std::ops::Range<usize>,
    imports: &DiskImports,
    depth: usize,
) -> Option<Vec<(String, Option<String>)>> {
    if depth > MAX_DEPTH {
        return None;
    }
    let b = script.file.text().as_bytes();
    let start = scan::skip_trivia(b, value.start);
    if script.file.text()[start..].starts_with("Object.assign") {
        let open = scan::skip_trivia(b, start + "Object.assign".len());
        if b.get(open) != Some(&b'(') {
            return None;
        }
        let mut all: Vec<(String, Option<String>)> = Vec::new();
        for arg in objects::arguments(script.file.text(), open)? {
            for (k, v) in merged_defines(script, arg, imports, depth + 1)? {
                all.retain(|(name, _)| *name != k);
                all.push((k, v));
            }
        }
        return Some(all);
    }
    let (script, at) = if b.get(start) == Some(&b'{') {
        (script.clone(), start)
    } else {
        match value_position(script, value.clone(), imports) {
            Some(found) => found,
            None => return no_defines_key(script, value, imports),
        }
    };
    let text = script.file.text();
    let o = objects::object(text, at)?;
    let values = o
        .entries
        .iter()
        .map(|(key, value)| {
            let code = text[value.clone()].trim();
            let value_text = match code {
                "true" | "false" => Some(code.to_string()),
                _ => value_position(&script, value.clone(), imports)
                    .and_then(|(s, at)| literal_at(&s, at, imports))
                    .map(|l| l.text),
            };
            (key.clone(), value_text)
        })
        .collect();
    Some(values)
}
